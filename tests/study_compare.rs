//! `compare` recovers a bias injected into synthetic replicates, through the library and
//! through the command line, and the study commands fail clearly without POV-Ray.
//!
//! The synthetic "reference" is a smooth image with hard edges; replicates are the reference
//! plus a known offset plus independent Gaussian noise (sigma 0.02, fixed seeds). With K = 4
//! at 160x120 the bias estimate B on 4x4 blocks has a standard error of about 4e-7 around
//! b^2 = 1.6e-5 (per block: sqrt(sigma_b^4 / 6 + b^2 sigma_b^2) with sigma_b = sigma / 4,
//! over 3600 block values), so sqrt(B) reads back 0.004 to within about 5e-5; the tolerance
//! below is ten times that.

use penumbra::output::{Image, write_exr};
use penumbra::study::TempDir;
use penumbra::study::compare::{Target, compare_to};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::process::Command;

const W: usize = 160;
const H: usize = 120;
const SIGMA: f64 = 0.02;
const K: usize = 4;
const OFFSET: f32 = 0.004;
/// Ten standard errors of sqrt(B) (see the module comment).
const BIAS_TOLERANCE: f64 = 5e-4;

fn reference() -> Image {
    Image::from_fn(W, H, |x, y| {
        let (x, y) = (x as f32, y as f32);
        let mut c = [0.2 + 0.4 * x / W as f32, 0.3 + 0.1 * (y / 11.0).sin(), 0.5];
        if (x - 70.0).powi(2) + (y - 60.0).powi(2) < 900.0 {
            c = [0.8, 0.5, 0.2];
        }
        c
    })
}

fn gaussian(rng: &mut Pcg64) -> f32 {
    let u1: f64 = 1.0 - rng.random::<f64>();
    let u2: f64 = rng.random::<f64>();
    ((-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()) as f32
}

fn replicates(offset: f32, seed: u64) -> Vec<Image> {
    let r = reference();
    (0..K as u64)
        .map(|k| {
            let mut rng = Pcg64::seed_from_u64(seed * 100 + k);
            r.map(|v| v + offset + SIGMA as f32 * gaussian(&mut rng))
        })
        .collect()
}

#[test]
fn compare_recovers_an_injected_bias_and_the_noise() {
    let target = Target {
        image: reference(),
        half: Some(reference()),
    };
    let biased = compare_to(&replicates(OFFSET, 1), &target).expect("comparable");
    let split = biased.split.as_ref().expect("replicates give a split");
    println!("{biased}");
    assert!(
        (split.bias.sqrt_b() - f64::from(OFFSET)).abs() < BIAS_TOLERANCE,
        "sqrt(B) {} should be {OFFSET}",
        split.bias.sqrt_b()
    );
    // sqrt(V) has a relative standard error of about sqrt(2 / (3 * 57600)) = 0.3%.
    assert!(
        (split.sqrt_v - SIGMA).abs() < 0.05 * SIGMA,
        "{}",
        split.sqrt_v
    );
    // One image's RMSE mixes both: sqrt(b^2 + sigma^2).
    let expected = (f64::from(OFFSET).powi(2) + SIGMA * SIGMA).sqrt();
    assert!((biased.difference.rmse - expected).abs() < 0.05 * expected);

    let honest = compare_to(&replicates(0.0, 2), &target).expect("comparable");
    let sqrt_b = honest.split.as_ref().expect("split").bias.sqrt_b();
    assert!(sqrt_b < BIAS_TOLERANCE, "unbiased replicates read {sqrt_b}");
}

#[test]
fn compare_without_replicates_has_no_split_and_exact_metrics() {
    let r = reference();
    let shifted = r.map(|v| v + 0.25);
    let target = Target {
        image: r,
        half: None,
    };
    let c = compare_to(&[shifted], &target).expect("comparable");
    assert!(c.split.is_none());
    assert!((c.difference.rmse - 0.25).abs() < 1e-6);
    assert!((c.difference.mean_abs - 0.25).abs() < 1e-6);
    assert!((c.difference.max_abs - 0.25).abs() < 1e-6);
}

fn penumbra() -> Command {
    Command::new(env!("CARGO_BIN_EXE_penumbra"))
}

/// A fresh folder, removed when the test ends (passed or failed).
fn scratch(name: &str) -> TempDir {
    TempDir::new(&format!("study-{name}")).expect("temp dir")
}

/// The number after `label` in the command's output.
fn number_after(text: &str, label: &str) -> f64 {
    let rest = &text[text
        .find(label)
        .unwrap_or_else(|| panic!("no {label:?} in {text}"))
        + label.len()..];
    rest.split_whitespace()
        .next()
        .and_then(|w| w.parse().ok())
        .unwrap_or_else(|| panic!("no number after {label:?} in {text}"))
}

#[test]
fn the_compare_command_splits_bias_and_writes_a_difference_image() {
    let temp = scratch("compare");
    let dir = temp.path();
    let reference_path = dir.join("reference.exr");
    write_exr(&reference_path, &reference(), &[], &[]).expect("write reference");
    let mut paths = Vec::new();
    for (k, image) in replicates(OFFSET, 3).iter().enumerate() {
        let path = dir.join(format!("r{k}.exr"));
        write_exr(&path, image, &[], &[]).expect("write replicate");
        paths.push(path);
    }
    let diff = dir.join("diff.png");
    let output = penumbra()
        .arg("compare")
        .arg(&paths[0])
        .arg(&reference_path)
        .arg("--replicates")
        .args(&paths[1..])
        .arg("--diff")
        .arg(&diff)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let sqrt_b = number_after(&stdout, "bias sqrt(B)");
    assert!(
        (sqrt_b - f64::from(OFFSET)).abs() < BIAS_TOLERANCE,
        "{stdout}"
    );
    let png = image::open(&diff).expect("a readable PNG");
    assert!(png.width() >= W as u32 && png.height() > H as u32);
}

#[test]
fn compare_reports_a_size_mismatch_and_a_missing_file() {
    let temp = scratch("mismatch");
    let dir = temp.path();
    let a = dir.join("a.exr");
    let b = dir.join("b.exr");
    write_exr(&a, &Image::filled(8, 8, [0.5; 3]), &[], &[]).expect("write");
    write_exr(&b, &Image::filled(8, 4, [0.5; 3]), &[], &[]).expect("write");
    let output = penumbra()
        .arg("compare")
        .arg(&a)
        .arg(&b)
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success());
    assert!(
        stderr.contains("the reference is 8x4, expected 8x8"),
        "{stderr}"
    );

    let output = penumbra()
        .arg("compare")
        .arg(dir.join("missing.exr"))
        .arg(&b)
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success());
    assert!(stderr.contains("missing.exr"), "{stderr}");
}

/// With no povray on PATH, `reference` and `converge --povray` stop at once and say why.
#[test]
fn study_commands_fail_clearly_without_povray() {
    let temp = scratch("nopovray");
    let dir = temp.path();
    let scene = format!("{}/scenes/checker.pov", env!("CARGO_MANIFEST_DIR"));
    let reference = format!(
        "{}/tests/references/checker.exr",
        env!("CARGO_MANIFEST_DIR")
    );
    let runs = [
        vec![
            "reference".to_string(),
            scene.clone(),
            "--output".into(),
            dir.join("r.exr").display().to_string(),
        ],
        vec![
            "converge".to_string(),
            scene,
            "--reference".into(),
            reference,
            "--povray".into(),
            "--output-dir".into(),
            dir.join("c").display().to_string(),
        ],
    ];
    for args in runs {
        let output = penumbra()
            .args(&args)
            .env("PATH", dir)
            .output()
            .expect("runs");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success(), "{args:?} succeeded");
        assert!(
            stderr.contains("`povray` was not found on PATH"),
            "{args:?}: {stderr}"
        );
    }
}
