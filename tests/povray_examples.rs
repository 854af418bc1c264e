//! POV-Ray's own example scenes (the povray-examples package), rendered by penumbra and
//! compared with POV-Ray's converged output (shared/testing-statistics.md): K = 4 seeds,
//! N = 64 samples, 160x120, sqrt(B) <= 0.005 and no failing tile. Where a scene cannot pass
//! yet, the reason stands beside it and the test says so instead of staying silent.

use std::path::{Path, PathBuf};

use penumbra::lang::{LoadOptions, load_scene};
use penumbra::render::RenderOptions;
use penumbra::study::{self, SQRT_B_THRESHOLD};

const EXAMPLES: &str = "/usr/share/povray-3.7/scenes";

/// (scene, why it cannot pass yet)
const SCENES: &[(&str, Option<&str>)] = &[
    // The language (issue 3): macros, local scope, recursion.
    ("language/macros/local.pov", None),
    ("language/macros/macro1.pov", None),
    ("language/macros/macro2.pov", None),
    ("language/macros/macro3.pov", None),
    ("language/macros/macro4.pov", None),
    // Lights and distributed effects (issue 6).
    ("lights/arealit1.pov", None),
    ("lights/arealit2.pov", None),
    ("lights/arealit3.pov", None),
    ("lights/soft.pov", None),
    ("lights/fillite.pov", None),
    ("lights/parallel_lights.pov", None),
    ("camera/focalblur.pov", None),
    // Geometry (issue 4): a function-shaped height field of triangles, columns of
    // cylinders and tori textured by `#default` (a 3.6 scene), shapes2.inc's intersections of
    // planes and cones (assumed_gamma 2.2), transforms.inc's macros, and the general quartic
    // with POV-Ray's 35-term coefficient order.
    ("advanced/sombrero.pov", None),
    ("advanced/bwstripe.pov", None),
    ("incdemo/shapes2.pov", None),
    ("incdemo/transforms.pov", None),
    ("objects/quartic/torus.pov", None),
    ("objects/quartic/piriform.pov", None),
    // Appearance (issue 5).
    ("textures/patterns/brick.pov", None),
    ("textures/patterns/gradient.pov", None),
    (
        "textures/patterns/hexagon.pov",
        Some(
            "sqrt(B) 0.0009, but 3 tiles fail along one groove of the normal row's box (the hexagon pattern used as a normal): POV-Ray shows a groove there that penumbra does not; the pigment row and every other groove match",
        ),
    ),
    ("textures/patterns/leopard.pov", None),
    ("textures/patterns/onion.pov", None),
    ("textures/patterns/radial.pov", None),
    ("textures/patterns/spiral1.pov", None),
    ("textures/patterns/spiral2.pov", None),
    ("interior/atten1.pov", None),
    ("interior/iortest.pov", None),
    ("incdemo/finish.pov", None),
    ("incdemo/metals/brasses.pov", None),
    ("incdemo/metals/chromes.pov", None),
    ("incdemo/metals/coppers.pov", None),
    ("incdemo/metals/golds.pov", None),
    ("incdemo/metals/silvers.pov", None),
];

/// The verdict, `Ok(None)` when the examples are not installed, `Err` when the scene does not
/// load.
fn verdict(scene: &str) -> Result<Option<study::Verdict>, String> {
    let path = Path::new(EXAMPLES).join(scene);
    if !path.exists() {
        println!("{scene}: skipped, the povray-examples package is not installed");
        return Ok(None);
    }
    let options = LoadOptions {
        include_paths: vec![path.parent().expect("folder").to_path_buf()],
        image_width: 160,
        image_height: 120,
        ..LoadOptions::default()
    };
    let scene_model = load_scene(&path, &options)
        .map_err(|d| d.to_string())?
        .scene;
    let name = scene.trim_end_matches(".pov").replace('/', "_");
    let reference = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/references/examples")
        .join(format!("{name}.exr"));
    let reference = study::read_reference(&reference).expect("committed reference");
    let images: Vec<_> = (0..4)
        .map(|k| {
            let o = RenderOptions {
                width: 160,
                height: 120,
                samples_per_pixel: 64,
                seed: 100 + k,
                ..RenderOptions::default()
            };
            penumbra::render_scene(&scene_model, &o, &())
                .expect("renders")
                .0
        })
        .collect();
    Ok(Some(
        study::evaluate(&images, &reference.full, &reference.half).expect("comparable"),
    ))
}

#[test]
fn povray_examples_converge_to_povray() {
    let mut failures = Vec::new();
    for &(scene, reason) in SCENES {
        let v = match (verdict(scene), reason) {
            (Ok(Some(v)), _) => v,
            (Ok(None), _) => continue,
            (Err(e), Some(reason)) => {
                println!("{scene}: not rendered: {reason}\n  ({e})");
                continue;
            }
            (Err(e), None) => {
                failures.push(format!("{scene}: does not load: {e}"));
                continue;
            }
        };
        match reason {
            // Known differences are still measured, so a fix shows up here.
            Some(reason) if v.passes(SQRT_B_THRESHOLD) => {
                println!("{scene}: {v}\n  passes now: remove its reason ({reason})")
            }
            Some(reason) => println!("{scene}: KNOWN FAILING: {reason}\n  {v}"),
            None => {
                println!("{scene}: {v}");
                if !v.passes(SQRT_B_THRESHOLD) {
                    failures.push(format!("{scene}: {v}"));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
