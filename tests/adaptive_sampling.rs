//! Samples where the error is, without bias. Adaptive sampling: a pilot pass measures the
//! noise and each pixel's further samples follow its neighbours' noise (not its own, so the
//! pilot's samples stay in its mean unbiased). Covering the light grid: a pixel's samples
//! share out the points of POV-Ray's area-light grid between them. Both pass the
//! statistical test against POV-Ray and lower the noise for the same samples per pixel.

use std::path::Path;

use penumbra::lang::{LoadOptions, load_scene};
use penumbra::output::Image;
use penumbra::render::{LightSamples, RenderOptions};
use penumbra::study::{self, SQRT_B_THRESHOLD};

#[test]
fn adaptive_sampling_is_unbiased_and_lowers_the_noise() {
    let (scene, reference) = soft_shadow();
    let render = |adaptive: bool| -> Vec<Image> {
        (0..4)
            .map(|k| {
                let o = RenderOptions {
                    width: 160,
                    height: 120,
                    samples_per_pixel: 16,
                    seed: 70 + k,
                    adaptive,
                    ..RenderOptions::default()
                };
                penumbra::render_scene(&scene, &o, &()).expect("renders").0
            })
            .collect()
    };
    let uniform = study::evaluate(&render(false), &reference.full, &reference.half).unwrap();
    let adaptive = study::evaluate(&render(true), &reference.full, &reference.half).unwrap();
    println!("uniform 16 spp:  {uniform}");
    println!("adaptive 16 spp: {adaptive}");
    assert!(adaptive.passes(SQRT_B_THRESHOLD), "{adaptive}");
    // sqrt(V) is a mean over pixels of the per-pixel variance: the quantity a proportional
    // allocation minimises. Noise is concentrated in the penumbrae here, so it must drop.
    assert!(
        adaptive.sqrt_v < 0.9 * uniform.sqrt_v,
        "adaptive {} vs uniform {}",
        adaptive.sqrt_v,
        uniform.sqrt_v
    );
}

#[test]
fn covering_the_light_grid_is_unbiased_and_lowers_the_noise() {
    let (scene, reference) = soft_shadow();
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

/// scenes/soft_shadow.pov at 160x120 and its committed POV-Ray reference.
fn soft_shadow() -> (penumbra::scene::Scene, study::reference::Reference) {
    let root = env!("CARGO_MANIFEST_DIR");
    let options = LoadOptions {
        image_width: 160,
        image_height: 120,
        ..LoadOptions::default()
    };
    let scene = load_scene(
        Path::new(&format!("{root}/scenes/soft_shadow.pov")),
        &options,
    )
    .expect("loads")
    .scene;
    let reference = study::read_reference(Path::new(&format!(
        "{root}/tests/references/soft_shadow.exr"
    )))
    .expect("reference");
    (scene, reference)
}
