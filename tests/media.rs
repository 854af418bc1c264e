//! Participating media against answers known in closed form.
//!
//! - A homogeneous absorbing slab of thickness d transmits exp(-sigma d). Written with a
//!   constant density the estimator uses the exact exponential (no noise at all); written
//!   with a density pattern that happens to be constant it uses ratio tracking, a random
//!   estimate, whose mean over the image must lie within 3 standard errors of the answer
//!   (a false failure one time in 370).
//! - A homogeneous sphere of radius R that emits e and absorbs a, seen through an
//!   orthographic camera: the light summed over the image is the integral over the disc
//!   of e (1 - exp(-a L)) / a for chords L = 2 sqrt(R^2 - r^2), which is
//!   (2 pi e / a) (R^2 / 2 - (1 - exp(-b R) (1 + b R)) / b^2) with b = 2 a.

use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::render::RenderOptions;

fn render(source: &str, size: usize, spp: u32) -> Vec<[f64; 3]> {
    let loaded = load_scene_source("media.pov", source, &LoadOptions::default())
        .unwrap_or_else(|d| panic!("{d}"));
    let options = RenderOptions {
        width: size,
        height: size,
        samples_per_pixel: spp,
        seed: 11,
        ..RenderOptions::default()
    };
    let image = penumbra::render_scene(&loaded.scene, &options, &())
        .expect("render")
        .0;
    (0..size * size)
        .map(|i| {
            let p = image.get(i % size, i / size);
            [f64::from(p[0]), f64::from(p[1]), f64::from(p[2])]
        })
        .collect()
}

/// An emitting white wall seen through a slab of absorbing media `thickness` deep.
fn slab(media: &str, thickness: f64) -> String {
    format!(
        "#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ orthographic location <0, 0, -5> look_at 0 right x up y }}
plane {{ -z, -10 pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} }}
box {{ <-3, -3, 0>, <3, 3, {thickness}> hollow pigment {{ rgbt 1 }}
  interior {{ media {{ {media} }} }} }}
"
    )
}

fn mean_and_error(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

#[test]
fn a_uniform_absorbing_slab_transmits_exactly_exp_minus_sigma_d() {
    let sigma: [f64; 3] = [0.2, 0.7, 1.5];
    let d = 1.3;
    let media = format!("absorption <{}, {}, {}>", sigma[0], sigma[1], sigma[2]);
    let pixels = render(&slab(&media, d), 16, 4);
    for (c, s) in sigma.iter().enumerate() {
        let want = (-s * d).exp();
        for p in &pixels {
            // The film's fixed point rounds at 2^-32 or so; f32 output at 2^-24.
            assert!(
                (p[c] - want).abs() < 1e-6,
                "channel {c}: {} vs {want}",
                p[c]
            );
        }
    }
}

#[test]
fn ratio_tracking_through_a_patterned_slab_is_unbiased() {
    // A gradient whose colour map is 1 at both ends: a constant density the renderer
    // cannot tell from a varying one, so it tracks.
    let sigma = 1.1;
    let d = 1.5;
    let media =
        format!("absorption {sigma} density {{ gradient x color_map {{ [0 rgb 1] [1 rgb 1] }} }}");
    let pixels = render(&slab(&media, d), 32, 4);
    let values: Vec<f64> = pixels.iter().map(|p| p[0]).collect();
    let (mean, se) = mean_and_error(&values);
    let want = (-sigma * d).exp();
    println!("tracked transmittance {mean:.5} +- {se:.5}, exact {want:.5}");
    assert!(se > 0.0, "ratio tracking should be random");
    assert!((mean - want).abs() < 3.0 * se, "{mean} +- {se} vs {want}");
}

#[test]
fn an_emitting_absorbing_sphere_sends_the_closed_form_total() {
    let (e, a, r) = (0.4, 0.8, 1.0);
    let size = 96;
    let width = 2.4;
    let source = format!(
        "#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ orthographic location <0, 0, -5> look_at 0 right x*{width} up y*{width} }}
sphere {{ 0, {r} hollow pigment {{ rgbt 1 }}
  interior {{ media {{ emission {e} absorption {a} }} }} }}
"
    );
    let pixels = render(&source, size, 16);
    let pixel_area = (width / size as f64).powi(2);
    let values: Vec<f64> = pixels.iter().map(|p| p[1] * pixel_area).collect();
    let total: f64 = values.iter().sum();
    let b = 2.0 * a;
    let want = 2.0 * std::f64::consts::PI * e / a
        * (r * r / 2.0 - (1.0 - (-b * r).exp() * (1.0 + b * r)) / (b * b));
    // The estimate is random only through where the pixel samples fall on the disc's
    // edge; its spread over seeds is far below this (0.2%, set by the edge pixels).
    println!("emitted total {total:.5}, closed form {want:.5}");
    assert!((total / want - 1.0).abs() < 0.002, "{total} vs {want}");
}

/// Media draw their distances from fixed sampler dimensions and their tracking steps from
/// streams keyed by pixel, sample and dimension (or by the shadow ray itself), so the film
/// is the same bit for bit whatever the thread count or the split of the samples.
#[test]
fn media_renders_are_identical_for_any_thread_count_and_sample_split() {
    for name in ["media_absorbing.pov", "media_atmospheric.pov"] {
        let path = format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
        let options = LoadOptions {
            image_width: 40,
            image_height: 30,
            ..LoadOptions::default()
        };
        let scene = penumbra::lang::load_scene(path.as_ref(), &options)
            .expect("loads")
            .scene;
        let base = RenderOptions {
            width: 40,
            height: 30,
            samples_per_pixel: 6,
            seed: 5,
            threads: Some(2),
            ..RenderOptions::default()
        };
        let (whole, _) = penumbra::render_film(&scene, &base, &()).expect("renders");
        let one = RenderOptions {
            threads: Some(1),
            ..base.clone()
        };
        let (single, _) = penumbra::render_film(&scene, &one, &()).expect("renders");
        assert_eq!(whole.pixels, single.pixels, "{name}: threads");
        let mut merged = None;
        for range in [0..2, 2..6] {
            let part = RenderOptions {
                sample_range: Some(range),
                ..base.clone()
            };
            let (film, _) = penumbra::render_film(&scene, &part, &()).expect("renders");
            match &mut merged {
                None => merged = Some(film),
                Some(m) => m.merge(&film),
            }
        }
        assert_eq!(
            merged.expect("two parts").pixels,
            whole.pixels,
            "{name}: split"
        );
    }
}
