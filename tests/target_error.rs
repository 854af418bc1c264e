//! `--target-error`: passes until the estimated noise is below the target. The stopping
//! rule and the noise-following allocation must not bias the image: renders to a target
//! still pass the statistical test against POV-Ray's converged reference (K = 4 seeds,
//! sqrt(B) <= 0.005, no failing tile), and each reaches the RMSE it was asked for against
//! that reference.

use std::path::PathBuf;

use penumbra::lang::{LoadOptions, load_scene};
use penumbra::render::RenderOptions;
use penumbra::render::target::TargetError;
use penumbra::study::{self, SQRT_B_THRESHOLD};

const TARGET: f64 = 0.005;

fn check(scene: &str) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let options = LoadOptions {
        image_width: 160,
        image_height: 120,
        ..LoadOptions::default()
    };
    let model = load_scene(&root.join(format!("scenes/{scene}.pov")), &options)
        .expect("loads")
        .scene;
    let reference = study::read_reference(&root.join(format!("tests/references/{scene}.exr")))
        .expect("committed reference");
    let mut images = Vec::new();
    for k in 0..4 {
        let o = RenderOptions {
            width: 160,
            height: 120,
            seed: 300 + k,
            target_error: Some(TargetError {
                value: TARGET,
                relative: false,
                max_spp: 1024,
            }),
            ..RenderOptions::default()
        };
        let (image, stats) = penumbra::render_scene(&model, &o, &()).expect("renders");
        let rmse = study::rmse(&image, &reference.full).expect("comparable");
        let spp = stats.samples as f64 / (160.0 * 120.0);
        println!("{scene} seed {}: RMSE {rmse:.5} at {spp:.1} spp", 300 + k);
        assert!(
            rmse <= TARGET,
            "{scene}: RMSE {rmse} above the target {TARGET}"
        );
        assert!(
            spp < 1024.0,
            "{scene}: stopped by the sample cap, not the target"
        );
        images.push(image);
    }
    let verdict = study::evaluate(&images, &reference.full, &reference.half).expect("comparable");
    println!("{scene}: {verdict:?}");
    assert!(verdict.passes(SQRT_B_THRESHOLD), "{scene}: {verdict:?}");
}

#[test]
fn soft_shadows_to_a_target_error_are_unbiased() {
    check("soft_shadow");
}

#[test]
fn area_illumination_to_a_target_error_is_unbiased() {
    check("area_illumination");
}
