//! Fog as POV-Ray computes it, beyond the formulas unit-tested in src/render/fog.rs.
//!
//! Turbulent fog matches POV-Ray in distribution: the quantiles of the attenuation over a
//! black plane behind a white fog (scenes and POV-Ray's figures in
//! tests/references/fog_stats.txt, written by scripts/fog_reference.py).
//!
//! Why the tolerance is a fraction of the spread: about 1600 noise cells are in view, so a
//! quantile of either image has a sampling spread near 0.004 of the 5%-95% range (for
//! independent cells: sqrt(p (1 - p) / n) over the density); two independent noises differ
//! by sqrt(2) of that, and 4 standard deviations are 0.022 of the range. penumbra's fog
//! noise is a fit to POV-Ray's (within 0.013 of its range), so 0.05 of the range holds a
//! correct fog and fails one whose turbulence is off by a tenth.

use std::path::PathBuf;

use penumbra::lang::{LoadOptions, load_scene_source};
use penumbra::render::RenderOptions;
use penumbra::study::distribution::{numbers, quantile, table_rows};

const SIZE: usize = 256;
const TOLERANCE: f64 = 0.05;

fn scene(body: &str) -> String {
    format!(
        "#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ orthographic location <0, 1, 0> look_at <0, 1, 1> right x*20 up y*20 }}
plane {{ -z, -10 pigment {{ rgb 0 }} finish {{ ambient 1 diffuse 0 }} }}
fog {{ {body} color rgb 1 }}
"
    )
}

fn render(source: &str, size: usize) -> penumbra::output::Image {
    let loaded = load_scene_source("fog.pov", source, &LoadOptions::default())
        .unwrap_or_else(|d| panic!("{d}"));
    let options = RenderOptions {
        width: size,
        height: size,
        samples_per_pixel: 1,
        seed: 7,
        ..RenderOptions::default()
    };
    penumbra::render_scene(&loaded.scene, &options, &())
        .expect("render")
        .0
}

/// The 19 quantiles of 1 - value over penumbra's render.
fn quantiles(body: &str) -> Vec<f64> {
    let image = render(&scene(body), SIZE);
    let mut a: Vec<f64> = (0..SIZE * SIZE)
        .map(|i| 1.0 - f64::from(image.get(i % SIZE, i / SIZE)[0]))
        .collect();
    a.sort_by(f64::total_cmp);
    (1..20).map(|i| quantile(&a, f64::from(i) / 20.0)).collect()
}

#[test]
fn turbulent_fog_matches_povray_in_distribution() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/references/fog_stats.txt");
    let text = std::fs::read_to_string(&path).expect("fog_stats.txt; run scripts/fog_reference.py");
    let mut failures = Vec::new();
    for row in table_rows(&text) {
        let (name, body) = (row[0], row[1]);
        let want = numbers(row[2]).expect("quantiles");
        let got = quantiles(body);
        let spread = want[18] - want[0];
        let worst = want
            .iter()
            .zip(&got)
            .map(|(w, g)| (w - g).abs())
            .fold(0.0, f64::max);
        println!(
            "{name:20} spread {spread:.4} (penumbra {:.4}), worst quantile difference {worst:.4} ({:.3} of the spread)",
            got[18] - got[0],
            worst / spread
        );
        if worst > TOLERANCE * spread {
            failures.push(format!(
                "{name}: {worst:.4} > {:.4}; povray {want:.4?}, penumbra {got:.4?}",
                TOLERANCE * spread
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// POV-Ray computes no fog for a camera inside a solid object, and fog inside a hollow one
/// (povray, a white sphere of radius 20 around the camera, black fog of distance 10: 1.0
/// solid, 0.1353 = exp(-2) hollow).
#[test]
fn no_fog_for_a_camera_inside_a_solid_object() {
    let seen = |hollow: &str| {
        let source = format!(
            "#version 3.7;
global_settings {{ assumed_gamma 1 }}
camera {{ location 0 look_at z angle 1 }}
sphere {{ 0, 20 pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} {hollow} }}
fog {{ distance 10 color rgb 0 }}
"
        );
        f64::from(render(&source, 1).get(0, 0)[0])
    };
    assert!((seen("") - 1.0).abs() < 1e-6, "{}", seen(""));
    assert!(
        (seen("hollow") - (-2.0f64).exp()).abs() < 1e-4,
        "{}",
        seen("hollow")
    );
}

/// A `media_attenuation` light dims through fog only outside solid objects (povray: a disc
/// inside a clear solid sphere of radius 5, lit from 20 away through fog of distance 10 and
/// seen from 10 away, reads 0.13538 = exp(-0.5) exp(-1.5)).
#[test]
fn lights_dim_through_fog_outside_solid_objects() {
    let source = "#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -10> look_at 0 angle 0.5 }
sphere { 0, 5 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } interior { ior 1 } }
disc { 0, -z, 2 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0, 0, -20> rgb 1 media_attenuation on }
fog { distance 10 color rgb 0 }
";
    let seen = f64::from(render(source, 1).get(0, 0)[0]);
    assert!((seen - (-2.0f64).exp()).abs() < 3e-4, "{seen}");
}
