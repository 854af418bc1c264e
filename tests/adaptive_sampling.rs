//! Samples where the error is, without bias. Adaptive sampling: a discarded pilot pass
//! measures each pixel's noise and cost and finds the penumbrae, and the second pass covers
//! the light grid only there and shares the rest of the time by noise. Covering the light grid: a pixel's samples
//! share out the points of POV-Ray's area-light grid between them. Both pass the
//! statistical test against POV-Ray and lower the noise for the same samples per pixel.

use std::path::Path;

use penumbra::lang::{LoadOptions, load_scene};
use penumbra::output::Image;
use penumbra::render::{LightSamples, RenderOptions};
use penumbra::study::{self, SQRT_B_THRESHOLD};

#[test]
fn adaptive_sampling_is_unbiased_and_lowers_the_noise_for_the_work() {
    // A 9x9 light: covering its grid costs 81 shadow rays a pixel, which adaptive sampling
    // spends only near the penumbrae the pilot finds.
    let (scene, reference) = scene_and_reference("area_circular_9x9");
    let render = |adaptive: bool| -> (Vec<Image>, u64) {
        let mut rays = 0;
        let images = (0..4)
            .map(|k| {
                let o = RenderOptions {
                    width: 160,
                    height: 120,
                    samples_per_pixel: 16,
                    seed: 70 + k,
                    adaptive,
                    ..RenderOptions::default()
                };
                let (image, stats) = penumbra::render_scene(&scene, &o, &()).expect("renders");
                rays += stats.rays.total();
                image
            })
            .collect();
        (images, rays)
    };
    let (uniform_images, uniform_rays) = render(false);
    let (adaptive_images, adaptive_rays) = render(true);
    let uniform = study::evaluate(&uniform_images, &reference.full, &reference.half).unwrap();
    let adaptive = study::evaluate(&adaptive_images, &reference.full, &reference.half).unwrap();
    println!("uniform 16 spp:  {uniform}, {uniform_rays} rays");
    println!("adaptive 16 spp: {adaptive}, {adaptive_rays} rays");
    assert!(adaptive.passes(SQRT_B_THRESHOLD), "{adaptive}");
    // Noise for the work: the variance times the rays traced is what an estimator's
    // efficiency is measured by (its inverse), and rays, unlike seconds, do not depend on
    // the machine. It must fall by a clear margin: measured 0.36 of uniform's with the
    // Sobol sampler (0.39 with the jittered grid, 0.60 when the pixels near penumbrae took
    // `spp` each rather than a share), and sqrt(V)
    // over 19,200 pixels and 4 seeds has a relative standard error under 1%, so the 0.7
    // bound is many standard errors from both the measurement and 1.
    let cost = |sqrt_v: f64, rays: u64| sqrt_v * (rays as f64).sqrt();
    assert!(
        cost(adaptive.sqrt_v, adaptive_rays) < 0.7 * cost(uniform.sqrt_v, uniform_rays),
        "adaptive {} with {adaptive_rays} rays vs uniform {} with {uniform_rays}",
        adaptive.sqrt_v,
        uniform.sqrt_v
    );
}

#[test]
fn covering_the_light_grid_is_unbiased_and_lowers_the_noise() {
    let (scene, reference) = scene_and_reference("soft_shadow");
    let render = |light_samples: LightSamples| -> Vec<Image> {
        (0..4)
            .map(|k| {
                let o = RenderOptions {
                    width: 160,
                    height: 120,
                    samples_per_pixel: 4,
                    seed: 90 + k,
                    light_samples,
                    ..RenderOptions::default()
                };
                penumbra::render_scene(&scene, &o, &()).expect("renders").0
            })
            .collect()
    };
    let one = study::evaluate(
        &render(LightSamples::Fixed(1)),
        &reference.full,
        &reference.half,
    )
    .unwrap();
    let cover = study::evaluate(
        &render(LightSamples::Cover),
        &reference.full,
        &reference.half,
    )
    .unwrap();
    println!("one shadow ray, 4 spp: {one}");
    println!("covering the grid, 4 spp: {cover}");
    assert!(cover.passes(SQRT_B_THRESHOLD), "{cover}");
    // 4 samples of a 5x5 light test 4 of its 25 points; covering it tests all of them, so
    // the penumbrae must get much quieter (measured: 0.47 of the noise).
    assert!(
        cover.sqrt_v < 0.7 * one.sqrt_v,
        "cover {} vs one {}",
        cover.sqrt_v,
        one.sqrt_v
    );
}

/// Under POV-Ray `adaptive` area lights the pilot shades a sample as the render does (the
/// adaptive rule), so its sample stays near penumbrae too: every camera ray ends in the
/// image (under a light that the render covers instead, the pilot's samples near penumbrae
/// are left out), and the render still passes the statistical test against POV-Ray.
#[test]
fn the_pilot_stays_under_adaptive_lights_without_bias() {
    let render = |name: &str| -> (Vec<Image>, Vec<(u64, u64)>) {
        let (scene, _) = scene_and_reference(name);
        (0..4)
            .map(|k| {
                let o = RenderOptions {
                    width: 160,
                    height: 120,
                    samples_per_pixel: 8,
                    seed: 110 + k,
                    adaptive: true,
                    ..RenderOptions::default()
                };
                let (image, stats) = penumbra::render_scene(&scene, &o, &()).expect("renders");
                (image, (stats.rays.camera, stats.samples))
            })
            .unzip()
    };
    let (images, counts) = render("area_adaptive");
    // Only the image's frame leaves its pilot samples out (`on_frame`): 2 (w + h) - 4.
    for &(camera, samples) in &counts {
        assert_eq!(
            camera - samples,
            2 * (160 + 120) - 4,
            "pilot samples were left out"
        );
    }
    let (_, covered) = render("soft_shadow");
    assert!(covered.iter().all(|&(camera, samples)| camera > samples));
    let (_, reference) = scene_and_reference("area_adaptive");
    let verdict = study::evaluate(&images, &reference.full, &reference.half).unwrap();
    println!("area_adaptive, adaptive 8 spp: {verdict}");
    assert!(verdict.passes(SQRT_B_THRESHOLD), "{verdict}");
}

/// An edge that runs along the image's frame, its other side outside the image, shows in
/// none of the neighbours of the frame pixels it crosses (beyond the frame there are none).
/// Here the top row is half covered (dark above y = 7.5, light below, every row under it
/// light): a top-row pixel whose two neighbours in the row drew light pilot samples looks
/// smooth. Judged from its neighbours alone and keeping its pilot sample (as inner pixels
/// do), such a pixel (probability 1/4) is its one pilot sample, squared error 1/4: the mean
/// squared error of the row is 1/16. Counting its own pilot value in and leaving the sample
/// out of its mean, it looks smooth only when all three drew light (1/8), and then takes one
/// fresh sample: 1/32. Over 4 seeds x 640 pixels the standard errors are 0.0021 and 0.0016,
/// so the bound halfway, 3/64, lies 7 and 10 of them from either. The row's mean tests the
/// bias: keeping the pilot sample of a pixel judged with it moves the mean from 1/2 to
/// 9/16 (a standard error of the mean is 0.005). That is the pilot of one sample per pixel
/// (`corner_pilot: false`); a pilot at the pixels' corners sees the edge between every
/// top-row pixel's upper and lower corners, and there the corners' ramp from 0 to 1 leaves
/// a sample a variance of 1/12 (not 1/4): its squared error must be below 1/64 (each pixel
/// takes more than one sample; the standard error is under 0.001).
#[test]
fn an_edge_along_the_frame_is_found_without_bias() {
    let source = "#version 3.7;
        global_settings { assumed_gamma 1.0 }
        camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x*640 up y*16 }
        plane { z, 0 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
        box { <-1000, 7.5, -5>, <1000, 100, -1> pigment { rgb 0 } finish { ambient 1 diffuse 0 } }";
    let options = LoadOptions {
        image_width: 640,
        image_height: 16,
        ..LoadOptions::default()
    };
    let scene = penumbra::lang::load_scene_source("frame.pov", source, &options)
        .expect("loads")
        .scene;
    let top_row = |corner_pilot: bool| -> (f64, f64) {
        let top: Vec<f64> = (0..4)
            .flat_map(|k| {
                let o = adaptive_options((640, 16), 4, 130 + k, corner_pilot);
                let image = penumbra::render_scene(&scene, &o, &()).expect("renders").0;
                (0..640)
                    .map(|x| f64::from(image.get(x, 0)[0]))
                    .collect::<Vec<_>>()
            })
            .collect();
        let n = top.len() as f64;
        let mse = top.iter().map(|v| (v - 0.5).powi(2)).sum::<f64>() / n;
        let mean = top.iter().sum::<f64>() / n;
        println!("top row (corner pilot {corner_pilot}): mean {mean:.4}, squared error {mse:.4}");
        (mean, mse)
    };
    let (mean, mse) = top_row(false);
    assert!(mse < 3.0 / 64.0, "squared error {mse}");
    assert!((mean - 0.5).abs() < 4.0 * 0.005, "mean {mean}");
    let (mean, mse) = top_row(true);
    assert!(mse < 1.0 / 64.0, "squared error {mse}");
    assert!((mean - 0.5).abs() < 4.0 * 0.005, "mean {mean}");
}

/// The pilot at the pixels' corners (src/render/corners.rs) against the pilot of one
/// sample per pixel, on scenes/checker.pov at 8 spp: both converge to POV-Ray's image (the
/// statistical test against the reference), and the corners' noise for the same samples
/// is lower by a clear margin. Over five sets of 4 seeds sqrt(V) of the corners over that of
/// the pixels' pilot was 0.76-0.89 (mean 0.81, standard deviation 0.05: the error is in a
/// few hundred edge pixels); with 8 seeds the deviation is about 0.035, so the bound 0.92
/// lies 3 deviations above the mean and 2.3 below 1, no gain.
#[test]
fn the_corner_pilot_is_unbiased_and_lowers_the_noise() {
    let (scene, reference) = scene_and_reference("checker");
    let verdict = |corner_pilot: bool| {
        let images: Vec<Image> = (0..8)
            .map(|k| {
                let o = adaptive_options((160, 120), 8, 150 + k, corner_pilot);
                penumbra::render_scene(&scene, &o, &()).expect("renders").0
            })
            .collect();
        study::evaluate(&images, &reference.full, &reference.half).unwrap()
    };
    let (pixels, corners) = (verdict(false), verdict(true));
    println!("checker 8 spp, pilot of pixels: {pixels}");
    println!("checker 8 spp, pilot of corners: {corners}");
    assert!(corners.passes(SQRT_B_THRESHOLD), "{corners}");
    assert!(
        corners.sqrt_v < 0.92 * pixels.sqrt_v,
        "{corners} against {pixels}"
    );
}

/// An adaptive render's options, its pilot at the corners where it may or not.
fn adaptive_options(
    (width, height): (usize, usize),
    spp: u32,
    seed: u64,
    corner_pilot: bool,
) -> RenderOptions {
    RenderOptions {
        width,
        height,
        samples_per_pixel: spp,
        seed,
        adaptive: true,
        corner_pilot,
        ..RenderOptions::default()
    }
}

/// A scene of scenes/ at 160x120 and its committed POV-Ray reference.
fn scene_and_reference(name: &str) -> (penumbra::scene::Scene, study::reference::Reference) {
    let root = env!("CARGO_MANIFEST_DIR");
    let options = LoadOptions {
        image_width: 160,
        image_height: 120,
        ..LoadOptions::default()
    };
    let scene = load_scene(Path::new(&format!("{root}/scenes/{name}.pov")), &options)
        .expect("loads")
        .scene;
    let reference =
        study::read_reference(Path::new(&format!("{root}/tests/references/{name}.exr")))
            .expect("reference");
    (scene, reference)
}
