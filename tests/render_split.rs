//! A render can be split by sample range (across machines, say) and the parts summed to
//! exactly the single-run film: the sampler is a pure function of (pixel, index, dimension,
//! seed) and the film keeps fixed-point sums.

use penumbra::lang::{LoadOptions, load_scene};
use penumbra::render::RenderOptions;

#[test]
fn sample_ranges_sum_to_the_whole_render() {
    let path = format!("{}/scenes/soft_shadow.pov", env!("CARGO_MANIFEST_DIR"));
    let options = LoadOptions {
        image_width: 48,
        image_height: 36,
        ..LoadOptions::default()
    };
    let scene = load_scene(path.as_ref(), &options).expect("loads").scene;
    let base = RenderOptions {
        width: 48,
        height: 36,
        samples_per_pixel: 16,
        seed: 11,
        ..RenderOptions::default()
    };
    let (whole, _) = penumbra::render_film(&scene, &base, &()).expect("renders");
    let mut merged = None;
    for range in [0..5, 5..6, 6..16] {
        let part = RenderOptions {
            sample_range: Some(range),
            threads: Some(1),
            ..base.clone()
        };
        let (film, _) = penumbra::render_film(&scene, &part, &()).expect("renders");
        match &mut merged {
            None => merged = Some(film),
            Some(m) => m.merge(&film),
        }
    }
    let merged = merged.expect("three parts");
    assert_eq!(merged.pixels, whole.pixels);
    // And the parts are not trivially equal to each other.
    let (first, _) = penumbra::render_film(
        &scene,
        &RenderOptions {
            sample_range: Some(0..8),
            ..base.clone()
        },
        &(),
    )
    .expect("renders");
    assert_ne!(first.means(), whole.means());
}
