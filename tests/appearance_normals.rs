//! Normals with POV-Ray's own noise-based perturbations (bumps, dents, wrinkles) match POV-Ray
//! in distribution (issue 5). penumbra's noise is its own (docs/noise.md), so the normals are
//! compared as images: a white plane at z = 0.37 + 3.1 k (k = 0..15; 0..63 for dents, whose
//! fine bands hang on the few highest noise peaks; fewer let one set of peaks decide: see
//! docs/appearance.md), 32 x 32 units at
//! 512 x 512 points, lit along the view, gives N.L (the cosine of the tilt); a second light
//! at 45 degrees gives the x slope of the perturbation. For both, the 19 quantiles (5% ..
//! 95%) must agree within 0.03 and the radially averaged power spectrum within 20% per octave
//! band (0.25 to 8 cycles per unit). POV-Ray's figures: tests/references/normal_stats.txt,
//! written by scripts/normal_reference.py (the thresholds' reasoning: tests/appearance_noise.rs).

use std::path::PathBuf;

use glam::DVec3;
use penumbra::appearance::perturbed_normal;
use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::scene::Texture;
use penumbra::study::distribution::{band_powers, numbers, quantile, table_rows};

const SIZE: usize = 512;
const EXTENT: f64 = 32.0;
const BANDS: [f64; 6] = [0.25, 0.5, 1.0, 2.0, 4.0, 8.0];
const SLOPE_AMOUNT: f64 = 0.05;
const QUANTILE_TOLERANCE: f64 = 0.03;
const SPECTRUM_TOLERANCE: f64 = 0.20;

struct Stats {
    quantiles: Vec<f64>,
    bands: Vec<f64>,
}

struct Reference {
    name: String,
    pattern: String,
    amount: f64,
    slices: usize,
    nl: Stats,
    slope: Stats,
}

fn references() -> Vec<Reference> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/references/normal_stats.txt");
    let text =
        std::fs::read_to_string(&path).expect("normal_stats.txt; run scripts/normal_reference.py");
    table_rows(&text)
        .into_iter()
        .map(|f| {
            let nums = |s: &str| numbers(s).expect("numbers");
            Reference {
                name: f[0].to_string(),
                pattern: f[1].to_string(),
                amount: f[2].parse().expect("amount"),
                slices: f[3].parse().expect("slices"),
                nl: Stats {
                    quantiles: nums(f[4]),
                    bands: nums(f[5]),
                },
                slope: Stats {
                    quantiles: nums(f[6]),
                    bands: nums(f[7]),
                },
            }
        })
        .collect()
}

fn texture(normal: &str) -> Texture {
    let source =
        format!("#version 3.7;\nplane {{ z, 0 pigment {{ rgb 1 }} normal {{ {normal} }} }}\n");
    let options = LoadOptions {
        image_width: SIZE as u32,
        image_height: SIZE as u32,
        ..LoadOptions::default()
    };
    let loaded =
        load_scene_source("normal.pov", &source, &options).unwrap_or_else(|d| panic!("{d}"));
    std::sync::Arc::unwrap_or_clone(loaded.scene.objects[0].texture.clone().expect("texture"))
}

/// The perturbed normal facing the camera (-z) at POV-Ray's pixel centres, row 0 at the top.
fn normals(t: &Texture, z: f64) -> Vec<DVec3> {
    let mut v = Vec::with_capacity(SIZE * SIZE);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let x = -EXTENT / 2.0 + (i as f64 + 0.5) * EXTENT / SIZE as f64;
            let y = EXTENT / 2.0 - (j as f64 + 0.5) * EXTENT / SIZE as f64;
            v.push(perturbed_normal(t, DVec3::new(x, y, z), -DVec3::Z));
        }
    }
    v
}

/// The largest quantile difference and the band power ratios (penumbra / POV-Ray).
fn compare(images: &[Vec<f64>], r: &Stats) -> (f64, Vec<f64>) {
    let mut sorted: Vec<f64> = images.concat();
    sorted.sort_by(f64::total_cmp);
    let max_q = (1..20)
        .map(|i| quantile(&sorted, i as f64 / 20.0))
        .zip(&r.quantiles)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    let mut bands = vec![0.0; BANDS.len() - 1];
    for img in images {
        for (b, v) in bands.iter_mut().zip(band_powers(img, SIZE, EXTENT, &BANDS)) {
            *b += v / images.len() as f64;
        }
    }
    (
        max_q,
        bands.iter().zip(&r.bands).map(|(a, b)| a / b).collect(),
    )
}

#[test]
fn noise_normals_match_povray_in_distribution() {
    let mut failures = Vec::new();
    for r in references() {
        let zs: Vec<f64> = (0..r.slices).map(|k| 0.37 + 3.1 * k as f64).collect();
        let lit = texture(&format!("{} {}", r.pattern, r.amount));
        let nl: Vec<Vec<f64>> = zs
            .iter()
            .map(|&z| normals(&lit, z).iter().map(|n| -n.z).collect())
            .collect();
        let small = texture(&format!("{} {SLOPE_AMOUNT}", r.pattern));
        let slope: Vec<Vec<f64>> = zs
            .iter()
            .map(|&z| {
                normals(&small, z)
                    .iter()
                    .map(|n| n.x / -n.z / SLOPE_AMOUNT)
                    .collect()
            })
            .collect();
        for (what, images, reference) in [("N.L", nl, &r.nl), ("slope", slope, &r.slope)] {
            let (max_q, ratios) = compare(&images, reference);
            let max_s = ratios.iter().map(|x| (x - 1.0).abs()).fold(0.0, f64::max);
            println!(
                "{:9} {what:5} max quantile diff {max_q:.4}; spectrum ratios {}",
                r.name,
                ratios
                    .iter()
                    .map(|x| format!("{x:.3}"))
                    .collect::<Vec<_>>()
                    .join(" ")
            );
            if max_q > QUANTILE_TOLERANCE || max_s > SPECTRUM_TOLERANCE {
                failures.push(format!(
                    "{} {what}: quantile {max_q:.4}, spectrum {max_s:.3}",
                    r.name
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
