//! The noise of penumbra's estimate falls at the rate the sampler promises
//! (testing-statistics.md, "Convergence rate"): sqrt(V) from replicate differences only, no
//! reference, on log-log axes against N.
//!
//! - Independent samples: slope -0.5 exactly in expectation, whatever the scene. sqrt(V)
//!   here averages 64 x 48 x 3 per-value variances of K = 4 replicates, so its relative
//!   standard error is about 1% (more with heavy tails) and the slope's, over a factor 64 in
//!   N, under 0.01: the window [-0.55, -0.45] is five standard errors wide each side.
//! - Stratified jittered samples: steeper, -0.75 near edges and -1 in smooth regions; a
//!   scene of texture edges must be clearly steeper than -0.6.

use penumbra::lang::{LoadOptions, load_scene};
use penumbra::render::{LightSamples, RenderOptions};
use penumbra::scene::Scene;
use penumbra::study::converge::log_log_slope;
use penumbra::study::noise_variance;
use std::path::PathBuf;

const WIDTH: usize = 64;
const HEIGHT: usize = 48;
const SEEDS: u64 = 4;
const SPP: [u32; 4] = [4, 16, 64, 256];

fn load(name: &str) -> Scene {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name);
    let options = LoadOptions {
        image_width: WIDTH as u32,
        image_height: HEIGHT as u32,
        ..LoadOptions::default()
    };
    load_scene(&path, &options)
        .unwrap_or_else(|d| panic!("{d}"))
        .scene
}

fn noise_slope(scene: &Scene, stratified: bool) -> f64 {
    let points: Vec<(f64, f64)> = SPP
        .iter()
        .map(|&spp| {
            let images: Vec<_> = (0..SEEDS)
                .map(|seed| {
                    let options = RenderOptions {
                        width: WIDTH,
                        height: HEIGHT,
                        samples_per_pixel: spp,
                        seed: 77 + seed,
                        stratified,
                        light_samples: LightSamples::Fixed(1),
                        ..RenderOptions::default()
                    };
                    penumbra::render_scene(scene, &options, &())
                        .expect("render")
                        .0
                })
                .collect();
            let v = noise_variance(&images).expect("replicates");
            (f64::from(spp), v.sqrt())
        })
        .collect();
    println!("stratified {stratified}: {points:?}");
    log_log_slope(&points).expect("a slope")
}

#[test]
fn independent_samples_converge_at_minus_one_half() {
    for name in ["soft_shadow.pov", "checker.pov"] {
        let slope = noise_slope(&load(name), false);
        println!("{name}: independent noise slope {slope:.3}");
        assert!(
            (-0.55..=-0.45).contains(&slope),
            "{name}: independent noise slope {slope:.3}"
        );
    }
}

#[test]
fn stratified_samples_converge_faster() {
    let scene = load("checker.pov");
    let stratified = noise_slope(&scene, true);
    let independent = noise_slope(&scene, false);
    println!("checker: stratified {stratified:.3}, independent {independent:.3}");
    assert!(
        stratified < -0.6 && stratified < independent - 0.1,
        "stratified slope {stratified:.3} is not steeper than independent {independent:.3}"
    );
}
