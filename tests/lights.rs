//! Lights and termination: the continuous area-light mode against POV-Ray with a fine grid,
//! and Russian roulette's unbiasedness, analytically and against roulette switched off.

use std::path::Path;

use penumbra::lang::{LoadOptions, load_scene, load_scene_source};
use penumbra::output::Image;
use penumbra::render::{AreaLightMode, RenderOptions};
use penumbra::scene::Scene;
use penumbra::study::distribution::erfc;
use penumbra::study::{self, SQRT_B_THRESHOLD};

const Z_STAR: f64 = 4.78;

fn scene_file(name: &str, width: u32, height: u32) -> Scene {
    let path = format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    let options = LoadOptions {
        image_width: width,
        image_height: height,
        ..LoadOptions::default()
    };
    match load_scene(Path::new(&path), &options) {
        Ok(l) => l.scene,
        Err(d) => panic!("{d}"),
    }
}

/// `k` replicates with seeds from `first_seed` on: independent of any other set that uses
/// other seeds.
fn replicates(scene: &Scene, options: &RenderOptions, k: u64, first_seed: u64) -> Vec<Image> {
    (0..k)
        .map(|i| {
            let o = RenderOptions {
                seed: first_seed + i,
                ..options.clone()
            };
            penumbra::render_scene(scene, &o, &()).expect("renders").0
        })
        .collect()
}

/// POV-Ray's grid with n = 33 (2^5 + 1, no jitter) is within about 3e-4 RMS of the
/// continuous emitter; penumbra's continuous mode must pass the statistical test against
/// it, and must fail against a coarse 2 x 2 grid (the light's four corners).
#[test]
fn continuous_area_lights_converge_to_a_fine_povray_grid() {
    let scene = scene_file("area_continuous.pov", 160, 120);
    let options = RenderOptions {
        width: 160,
        height: 120,
        samples_per_pixel: 64,
        area_lights: AreaLightMode::Continuous,
        ..RenderOptions::default()
    };
    let images = replicates(&scene, &options, 4, 500);
    let root = env!("CARGO_MANIFEST_DIR");
    let fine = study::read_reference(Path::new(&format!(
        "{root}/tests/references/area_continuous_n33.exr"
    )))
    .expect("reference");
    let v = study::evaluate(&images, &fine.full, &fine.half).expect("comparable");
    println!("continuous vs POV-Ray n=33: {v}");
    assert!(v.passes(SQRT_B_THRESHOLD), "{v}");
    let coarse = study::read_reference(Path::new(&format!(
        "{root}/tests/references/area_continuous_n2.exr"
    )))
    .expect("reference");
    let v = study::evaluate(&images, &coarse.full, &coarse.half).expect("comparable");
    println!("continuous vs POV-Ray n=2: {v}");
    assert!(
        !v.passes(SQRT_B_THRESHOLD),
        "the coarse grid should differ: {v}"
    );
}

/// Mean and variance of the sample mean of every pixel, over a set of replicates.
fn tile_stats(images: &[Image], x0: usize, y0: usize, size: usize) -> (f64, f64) {
    let k = images.len() as f64;
    let (w, h) = (images[0].width, images[0].height);
    let mut means = Vec::new();
    for im in images {
        let mut sum = 0.0;
        let mut n = 0.0;
        for y in y0..(y0 + size).min(h) {
            for x in x0..(x0 + size).min(w) {
                let p = im.get(x, y);
                sum += (p[0] + p[1] + p[2]) as f64 / 3.0;
                n += 1.0;
            }
        }
        means.push(sum / n);
    }
    let mean = means.iter().sum::<f64>() / k;
    let var = means.iter().map(|m| (m - mean).powi(2)).sum::<f64>() / (k - 1.0);
    (mean, var / k)
}

/// Upper tail of chi-square with `m` degrees of freedom (Wilson-Hilferty), enough to judge
/// p > 1e-3.
fn chi_square_upper_tail(x: f64, m: f64) -> f64 {
    let z = ((x / m).powf(1.0 / 3.0) - (1.0 - 2.0 / (9.0 * m))) / (2.0 / (9.0 * m)).sqrt();
    0.5 * erfc(z / std::f64::consts::SQRT_2)
}

/// Russian roulette keeps the expectation: replicates with it on and off agree tile by
/// tile (delta = 0, z* = 4.78) and in the chi-square aggregate (p > 1e-3). Roulette is at
/// work in this scene (fewer secondary rays with it), else the test would say nothing.
#[test]
fn roulette_on_and_off_agree() {
    let scene = scene_file("reflection.pov", 96, 72);
    let base = RenderOptions {
        width: 96,
        height: 72,
        samples_per_pixel: 16,
        ..RenderOptions::default()
    };
    let secondary = |roulette: bool| {
        let o = RenderOptions {
            roulette,
            ..base.clone()
        };
        penumbra::render_scene(&scene, &o, &())
            .expect("renders")
            .1
            .rays
            .secondary
    };
    let (cut, full) = (secondary(true), secondary(false));
    assert!(
        cut < full,
        "roulette ended no branch: {cut} rays against {full}"
    );
    let on = replicates(&scene, &base, 8, 500);
    let off = replicates(
        &scene,
        &RenderOptions {
            roulette: false,
            ..base.clone()
        },
        8,
        600,
    );
    let tile = 8;
    let (mut chi2, mut m, mut worst) = (0.0, 0.0, 0.0f64);
    for y0 in (0..72).step_by(tile) {
        for x0 in (0..96).step_by(tile) {
            let (a, va) = tile_stats(&on, x0, y0, tile);
            let (b, vb) = tile_stats(&off, x0, y0, tile);
            let se = (va + vb).sqrt();
            if se == 0.0 {
                assert_eq!(a, b, "deterministic tile differs at ({x0}, {y0})");
                continue;
            }
            let z = (a - b) / se;
            worst = worst.max(z.abs());
            chi2 += z * z;
            m += 1.0;
        }
    }
    let p = chi_square_upper_tail(chi2, m);
    println!("roulette on/off: {m} tiles, chi2 {chi2:.1}, p {p:.3}, worst |z| {worst:.2}");
    assert!(worst <= Z_STAR, "a tile differs: |z| = {worst}");
    assert!(p > 1e-3, "chi-square {chi2} over {m} tiles, p = {p}");
}

/// Two parallel mirrors of reflectivity rho, each glowing with Le: a ray bouncing between
/// them until the depth cap D sees Le (1 - rho^D) / (1 - rho), roulette or not.
#[test]
fn two_mirrors_give_the_geometric_series() {
    let (le, rho, depth) = (0.1f64, 0.7f64, 20u32);
    let source = format!(
        "#version 3.7;
global_settings {{ assumed_gamma 1.0 max_trace_level {depth} }}
camera {{ location <0, 0, 0> direction z right x up y }}
#declare F = finish {{ ambient 1 diffuse 0 reflection {rho} }}
plane {{ z, 1 pigment {{ rgb {le} }} finish {{ F }} }}
plane {{ z, -1 pigment {{ rgb {le} }} finish {{ F }} }}
"
    );
    let options = LoadOptions {
        image_width: 8,
        image_height: 8,
        ..LoadOptions::default()
    };
    let scene = load_scene_source("mirrors.pov", &source, &options)
        .expect("loads")
        .scene;
    let expected = le * (1.0 - rho.powi(depth as i32)) / (1.0 - rho);
    let render = RenderOptions {
        width: 8,
        height: 8,
        samples_per_pixel: 4096,
        ..RenderOptions::default()
    };
    let (image, _) = penumbra::render_scene(&scene, &render, &()).expect("renders");
    // Per-pixel means are independent estimates; their spread gives the standard error.
    let values: Vec<f64> = image.pixels.iter().map(|p| p[0] as f64).collect();
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    let se = (var / n).sqrt();
    println!("mirrors: mean {mean:.6}, expected {expected:.6}, standard error {se:.2e}");
    // Roulette must actually have been at work: the per-pixel values vary.
    assert!(var > 0.0, "no randomness: roulette never ran");
    assert!(
        (mean - expected).abs() <= Z_STAR * se + 1e-6,
        "mean {mean} vs {expected} (se {se})"
    );
}

/// The floor's brightness under fading glass, seen straight down through a small
/// orthographic window where the shadow is uniform.
fn shadowed_floor(objects: &str, light: &str, centre: &str) -> [f64; 3] {
    let source = format!(
        "#version 3.7;
global_settings {{ assumed_gamma 1.0 }}
camera {{ orthographic location {centre} + 10*y direction -y right 0.1*x up 0.1*z }}
light_source {{ {light} }}
plane {{ y, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}
#declare Glass = material {{
  texture {{ pigment {{ rgbf 1 }} finish {{ ambient 0 diffuse 0 }} }}
  interior {{ fade_distance 1 fade_power 1001 fade_color rgb <0.3, 0.5, 0.8> }}
}}
{objects}
"
    );
    let options = LoadOptions {
        image_width: 4,
        image_height: 4,
        ..LoadOptions::default()
    };
    let scene = load_scene_source("shadow.pov", &source, &options)
        .expect("loads")
        .scene;
    let render = RenderOptions {
        width: 4,
        height: 4,
        samples_per_pixel: 4,
        ..RenderOptions::default()
    };
    let (image, _) = penumbra::render_scene(&scene, &render, &()).expect("renders");
    let n = image.pixels.len() as f64;
    let mut mean = [0.0; 3];
    for p in &image.pixels {
        for c in 0..3 {
            mean[c] += p[c] as f64 / n;
        }
    }
    mean
}

fn assert_faded(got: [f64; 3], light: f64, distance: f64, tolerance: f64) {
    for (c, absorb) in [0.7, 0.5, 0.2].into_iter().enumerate() {
        let expected = light * (-absorb * distance).exp();
        assert!(
            (got[c] - expected).abs() < tolerance,
            "channel {c}: {} vs {expected} (fade over {distance})",
            got[c]
        );
    }
}

/// POV-Ray's shadow rays enter an interior at one crossing of its object and leave it at
/// the next, fading over the stretch since the previous crossing of anything (measured
/// with POV-Ray 3.7 on these scenes: 0.262 0.348 0.532 under the union, 0.3499 0.4719
/// 0.7405 under the nested spheres, which are these formulas to 1e-3).
#[test]
fn shadow_rays_fade_between_crossings_as_povray() {
    // Two overlapping spheres of one union, the light at 45 degrees: wherever the shadow
    // ray crosses both, it fades from entering one to meeting the other and from leaving
    // the first to leaving the second, sqrt(2) in all, for spheres one unit apart.
    let union = "union { sphere { <-0.5, 2, 0>, 1 } sphere { <0.5, 2, 0>, 1 } material { Glass } }";
    let got = shadowed_floor(
        union,
        "<1000, 1000, 0> color rgb 1 parallel point_at <0, 0, 0>",
        "<-2, 0, 0>",
    );
    assert_faded(got, 0.5f64.sqrt(), 2f64.sqrt(), 1e-4);
    // A merge has one surface: the ray meets the first sphere's front and the second's
    // back only, and fades over the whole stretch between.
    let merge = union.replace("union", "merge");
    let got = shadowed_floor(
        &merge,
        "<1000, 1000, 0> color rgb 1 parallel point_at <0, 0, 0>",
        "<-2, 0, 0>",
    );
    let d = 2f64.sqrt() / 2.0;
    let (a, b) = ((-0.5f64, 2.0f64), (0.5f64, 2.0f64));
    let along = |c: (f64, f64)| (c.0 + 2.0) * d + c.1 * d;
    let off = |c: (f64, f64)| ((c.0 + 2.0) * d - c.1 * d).abs();
    let enter = along(a) - (1.0 - off(a).powi(2)).sqrt();
    let leave = along(b) + (1.0 - off(b).powi(2)).sqrt();
    // (The chord changes a little over the window: 1e-3; pairing the crossings by
    // primitive gave 0.04.)
    assert_faded(got, 0.5f64.sqrt(), leave - enter, 1e-3);
    // A clear sphere inside a fading one, the light straight above: the shadow's centre
    // fades only over the 1.5 units above the clear sphere.
    // (Both out of the camera's sight, which looks down through them.)
    let nested = "sphere { <0, 2, 0>, 1.5 material { Glass } no_image }
sphere { <0, 1.5, 0>, 0.5 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } no_image }";
    let got = shadowed_floor(nested, "<0, 1000, 0> color rgb 1", "<0, 0, 0>");
    assert_faded(got, 1.0, 1.5, 1e-3);
}

/// A scene computed in gamma space decodes each sample before it is averaged, so its tree
/// ends as POV-Ray's does (a branch below adc_bailout is dropped), not by roulette, whose
/// noise the decoding would turn into brightness: a plane of transmit t before an emitter
/// of 1 under assumed_gamma 2.2 reads t^2.2 in POV-Ray (0.0000398 at t = 0.01; roulette
/// gave 0.00064) and 0 below adc_bailout (t = 0.003); the fixed-point film rounds at 1e-4
/// of it here.
#[test]
fn gamma_space_trees_end_at_adc_bailout() {
    for (t, want) in [(0.01f64, 0.01f64.powf(2.2)), (0.003, 0.0)] {
        let source = format!(
            "#version 3.7;
global_settings {{ assumed_gamma 2.2 }}
camera {{ orthographic location <0, 0, -5> look_at 0 right x*2 up y*2 }}
plane {{ z, 0 pigment {{ rgbt <1, 1, 1, {t}> }} finish {{ ambient 0 diffuse 0.5 }} }}
plane {{ z, 3 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 0 emission 1 }} }}
"
        );
        let options = LoadOptions {
            image_width: 8,
            image_height: 8,
            ..LoadOptions::default()
        };
        let scene = match load_scene_source("gamma.pov", &source, &options) {
            Ok(l) => l.scene,
            Err(d) => panic!("{d}"),
        };
        let render = RenderOptions {
            width: 8,
            height: 8,
            samples_per_pixel: 4,
            ..RenderOptions::default()
        };
        let image = replicates(&scene, &render, 1, 1).remove(0);
        for i in 0..64 {
            let v = f64::from(image.get(i % 8, i / 8)[0]);
            assert!(
                (v - want).abs() <= 1e-3 * want,
                "transmit {t}: pixel {i} reads {v}, POV-Ray's {want}"
            );
        }
    }
}
