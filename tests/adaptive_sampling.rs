//! Adaptive sampling: a discarded pilot pass decides where the samples go, so the estimate
//! stays unbiased (it passes the statistical test against POV-Ray), and for the same number
//! of samples its error is lower where noise is uneven.

use std::path::Path;

use penumbra::lang::{LoadOptions, load_scene};
use penumbra::output::Image;
use penumbra::render::RenderOptions;
use penumbra::study::{self, SQRT_B_THRESHOLD};

#[test]
fn adaptive_sampling_is_unbiased_and_lowers_the_noise() {
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
