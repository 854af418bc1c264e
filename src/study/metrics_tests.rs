//! The statistics on synthetic data: a box-filtered analytic "scene" with sharp edges plays
//! POV-Ray (k = 16 and k = 8 supersampling, like real references), and replicates are a
//! mean image plus independent Gaussian noise from fixed seeds.

use super::*;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::sync::OnceLock;

const W: usize = 160;
const H: usize = 120;
const SIGMA: f64 = 0.02;
const K: usize = 4;

/// Smooth shading plus a disk and a vertical step, both with hard edges, in pixel units.
fn scene(x: f64, y: f64) -> [f64; 3] {
    let mut c = [
        0.2 + 0.3 * x / W as f64,
        0.3 + 0.1 * (y / 15.0).sin(),
        0.4 + 0.2 * (x * y / (W * H) as f64),
    ];
    let (dx, dy) = (x - 60.3, y - 58.7);
    if dx * dx + dy * dy < 30.0 * 30.0 {
        c = [0.9, 0.6, 0.3];
    }
    if x > 120.3 {
        c = [c[0] + 0.4, c[1] + 0.3, c[2] + 0.5];
    }
    c
}

/// Box-filtered pixel values from k x k point samples, as a POV-Ray reference is made.
fn supersampled(k: usize, shift_x: f64) -> Image {
    Image::from_fn(W, H, |px, py| {
        let mut sum = [0.0f64; 3];
        for j in 0..k {
            for i in 0..k {
                let x = px as f64 + (i as f64 + 0.5) / k as f64 + shift_x;
                let y = py as f64 + (j as f64 + 0.5) / k as f64;
                let v = scene(x, y);
                for c in 0..3 {
                    sum[c] += v[c];
                }
            }
        }
        sum.map(|s| (s / (k * k) as f64) as f32)
    })
}

fn references() -> &'static (Image, Image) {
    static REFS: OnceLock<(Image, Image)> = OnceLock::new();
    REFS.get_or_init(|| (supersampled(16, 0.0), supersampled(8, 0.0)))
}

fn gaussian(rng: &mut Pcg64) -> f64 {
    // Box-Muller; 1 - u keeps the logarithm finite.
    let u1: f64 = 1.0 - rng.random::<f64>();
    let u2: f64 = rng.random::<f64>();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

fn replicates(mean: &Image, seed: u64) -> Vec<Image> {
    (0..K)
        .map(|k| {
            let mut rng = Pcg64::seed_from_u64(seed * 1000 + k as u64);
            mean.map(|v| v + (SIGMA * gaussian(&mut rng)) as f32)
        })
        .collect()
}

fn verdict_for(mean: &Image, seed: u64) -> Verdict {
    let (r, r2) = references();
    let verdict = evaluate(&replicates(mean, seed), r, r2).expect("valid inputs");
    println!("{verdict}");
    verdict
}

#[test]
fn unbiased_replicates_pass() {
    let (r, _) = references();
    for seed in 1..=3 {
        let verdict = verdict_for(r, seed);
        assert!(verdict.passes(SQRT_B_THRESHOLD), "{verdict}");
        assert!(verdict.sqrt_b < 0.002, "{verdict}");
        assert!((verdict.sqrt_v - SIGMA).abs() < 0.001, "{verdict}");
        assert_eq!(verdict.tiles.tested, 20 * 15 * 3);
    }
}

#[test]
fn unbiased_replicates_of_the_half_reference_also_pass() {
    // A renderer that converges to POV-Ray's integrand, not to its k = 16 quadrature.
    let verdict = verdict_for(&references().1, 4);
    assert!(verdict.passes(SQRT_B_THRESHOLD), "{verdict}");
}

#[test]
fn offset_of_0_01_fails() {
    let verdict = verdict_for(&references().0.map(|v| v + 0.01), 5);
    assert!(verdict.sqrt_b > SQRT_B_THRESHOLD, "{verdict}");
    assert!(!verdict.passes(SQRT_B_THRESHOLD));
}

#[test]
fn offset_of_0_004_reads_back_near_0_004() {
    let verdict = verdict_for(&references().0.map(|v| v + 0.004), 6);
    assert!((0.003..=0.0045).contains(&verdict.sqrt_b), "{verdict}");
}

#[test]
fn gain_of_3_percent_fails() {
    let verdict = verdict_for(&references().0.map(|v| v * 1.03), 7);
    assert!(verdict.sqrt_b > SQRT_B_THRESHOLD, "{verdict}");
    assert!(!verdict.passes(SQRT_B_THRESHOLD));
}

#[test]
fn half_pixel_shift_fails_in_bias_and_tiles() {
    let shifted = supersampled(16, 0.5);
    let verdict = verdict_for(&shifted, 8);
    assert!(verdict.sqrt_b > SQRT_B_THRESHOLD, "{verdict}");
    assert!(verdict.tiles.failed() > 0, "{verdict}");
    // Tiles away from the edges must not fail: the far left column is smooth.
    assert!(
        verdict.tiles.failures.iter().all(|t| t.x >= 24),
        "{verdict}"
    );
}

#[test]
fn a_local_bias_fails_its_tile_only() {
    let (r, _) = references();
    let mut biased = r.clone();
    for y in 40..48 {
        for x in 8..16 {
            let p = biased.get(x, y);
            biased.set(x, y, [p[0] + 0.05, p[1], p[2]]);
        }
    }
    let verdict = verdict_for(&biased, 9);
    assert_eq!(verdict.tiles.failed(), 1, "{verdict}");
    let failure = verdict.tiles.failures[0];
    assert_eq!(
        (
            failure.tile_x,
            failure.tile_y,
            failure.x,
            failure.y,
            failure.channel
        ),
        (1, 5, 8, 40, 0)
    );
    assert!((failure.d - 0.05).abs() < 0.01);
    assert!(!verdict.passes(SQRT_B_THRESHOLD));
}

#[test]
fn non_finite_values_are_found_and_fail() {
    let (r, r2) = references();
    let mut reps = replicates(r, 10);
    reps[2].set(7, 3, [0.0, f32::NAN, 0.0]);
    reps[3].set(1, 1, [f32::INFINITY, 0.0, 0.0]);
    let verdict = evaluate(&reps, r, r2).expect("valid inputs");
    assert_eq!(verdict.non_finite_count, 2);
    assert_eq!(
        verdict.non_finite[0],
        NonFinite {
            image: ImageRole::Replicate(2),
            x: 7,
            y: 3,
            channel: 1
        }
    );
    assert!(!verdict.passes(SQRT_B_THRESHOLD));
    assert!(verdict.to_string().starts_with("FAIL"));
    assert!(verdict.to_string().contains("replicate 2 at (7, 3)"));
}

#[test]
fn noise_variance_is_the_pairwise_definition() {
    // Three replicates of one pixel: pairs (0,1), (0,2), (1,2) of values 0, 1, 3.
    let reps: Vec<Image> = [0.0, 1.0, 3.0]
        .iter()
        .map(|&v| Image::filled(1, 1, [v, v, v]))
        .collect();
    let expected = ((1.0f64) + 9.0 + 4.0) / 2.0 / 3.0;
    assert!((noise_variance(&reps).expect("valid") - expected).abs() < 1e-12);
}

#[test]
fn bias_is_the_pairwise_definition_on_blocks() {
    // A 4x4 image is one block. Errors per replicate 0.1, 0.3; reference error 0.02.
    let r = Image::filled(4, 4, [0.5; 3]);
    let r2 = Image::filled(4, 4, [0.48; 3]);
    let reps = vec![Image::filled(4, 4, [0.6; 3]), Image::filled(4, 4, [0.8; 3])];
    let bias = bias_estimate(&reps, &r, &r2).expect("valid");
    assert!((bias.cross - 0.03).abs() < 1e-6);
    assert!((bias.reference_term - 0.0004).abs() < 1e-6);
    assert!((bias.b - 0.0296).abs() < 1e-6);
}

#[test]
fn partial_blocks_and_tiles_are_handled() {
    let r = Image::filled(10, 9, [0.5; 3]);
    let reps = vec![r.clone(), r.map(|v| v + 1e-3)];
    let report = tile_test(&reps, &r, &r).expect("valid");
    assert_eq!(report.tested, 2 * 2 * 3);
    assert_eq!(report.failed(), 0);
    assert!(bias_estimate(&reps, &r, &r).expect("valid").b.is_finite());
}

#[test]
fn bad_inputs_are_errors_not_panics() {
    let a = Image::filled(8, 8, [0.5; 3]);
    let b = Image::filled(8, 4, [0.5; 3]);
    assert!(matches!(
        noise_variance(std::slice::from_ref(&a)),
        Err(StudyError::TooFewReplicates { found: 1 })
    ));
    assert!(matches!(
        noise_variance(&[]),
        Err(StudyError::TooFewReplicates { found: 0 })
    ));
    assert!(matches!(
        evaluate(&[a.clone(), a.clone()], &b, &a),
        Err(StudyError::SizeMismatch { .. })
    ));
    assert!(evaluate(&[a.clone(), b.clone()], &a, &a).is_err());
    assert!(tile_test(&[a.clone(), a.clone()], &a, &b).is_err());
    let empty = Image::new(0, 0);
    assert!(evaluate(&[empty.clone(), empty.clone()], &empty, &empty).is_err());
    let broken = Image {
        width: 8,
        height: 8,
        pixels: vec![],
    };
    assert!(compare(&a, &broken).is_err());
    assert!(rmse(&a, &b).is_err());
}

#[test]
fn pixel_differences() {
    let a = Image::from_pixels(2, 1, vec![[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]).expect("size");
    let b = Image::from_pixels(2, 1, vec![[0.0, 0.0, 0.0], [1.0, 1.0, 1.6]]).expect("size");
    let d = compare(&a, &b).expect("same size");
    assert!((d.rmse - (0.36f64 / 6.0).sqrt()).abs() < 1e-6);
    assert!((d.mean_abs - 0.1).abs() < 1e-6);
    assert!((d.max_abs - 0.6).abs() < 1e-6);
    assert_eq!(d.max_at, (1, 0, 2));
    assert!((rmse(&a, &b).expect("ok") - d.rmse).abs() < 1e-12);
    assert!((mean_abs_error(&a, &b).expect("ok") - 0.1).abs() < 1e-6);
    assert!((max_abs_error(&a, &b).expect("ok") - 0.6).abs() < 1e-6);
}
