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
    // Lights and distributed effects (issue 6).
    ("lights/arealit1.pov", None),
    ("lights/arealit2.pov", None),
    ("lights/arealit3.pov", None),
    ("lights/soft.pov", None),
    ("lights/fillite.pov", None),
    ("lights/parallel_lights.pov", None),
    ("camera/focalblur.pov", None),
    // Appearance (issue 5).
    ("textures/patterns/brick.pov", None),
    ("textures/patterns/gradient.pov", None),
    ("textures/patterns/hexagon.pov", None),
    ("textures/patterns/leopard.pov", None),
    ("textures/patterns/onion.pov", None),
    ("textures/patterns/radial.pov", None),
    ("textures/patterns/spiral1.pov", None),
    ("textures/patterns/spiral2.pov", None),
    ("interior/atten1.pov", None),
    ("interior/iortest.pov", None),
    (
        "incdemo/finish.pov",
        Some("indexes an array of textures inside `texture { }`, which the language cannot yet"),
    ),
    ("incdemo/metals/brasses.pov", None),
    ("incdemo/metals/chromes.pov", None),
    ("incdemo/metals/coppers.pov", None),
    ("incdemo/metals/golds.pov", None),
    ("incdemo/metals/silvers.pov", None),
];

fn verdict(scene: &str) -> Option<study::Verdict> {
    let path = Path::new(EXAMPLES).join(scene);
    if !path.exists() {
        println!("{scene}: skipped, the povray-examples package is not installed");
        return None;
    }
    let name = scene.trim_end_matches(".pov").replace('/', "_");
    let reference = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/references/examples")
        .join(format!("{name}.exr"));
    let reference = study::read_reference(&reference).expect("committed reference");
    let options = LoadOptions {
        include_paths: vec![path.parent().expect("folder").to_path_buf()],
        image_width: 160,
        image_height: 120,
        ..LoadOptions::default()
    };
    let scene_model = match load_scene(&path, &options) {
        Ok(l) => l.scene,
        Err(d) => panic!("{d}"),
    };
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
    Some(study::evaluate(&images, &reference.full, &reference.half).expect("comparable"))
}

#[test]
fn povray_examples_converge_to_povray() {
    let mut failures = Vec::new();
    for &(scene, reason) in SCENES {
        if let Some(reason) = reason {
            println!("{scene}: not tested: {reason}");
            continue;
        }
        if let Some(v) = verdict(scene) {
            println!("{scene}: {v}");
            if !v.passes(SQRT_B_THRESHOLD) {
                failures.push(format!("{scene}: {v}"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
