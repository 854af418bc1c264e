//! A fast sample of the corpus-wide comparison (docs/corpus.md, `penumbra corpus`): about 20
//! of POV-Ray's example scenes, classified and judged by the instrument's own code
//! (penumbra::study::corpus) against POV-Ray references committed under
//! tests/references/examples/ (160x120, k = 16 and 8). K = 4 seeds, 64 samples per pixel.
//! Each scene must pass the test its classification names; for the distribution-test scenes
//! a 20% brighter penumbra must fail it, so the phase-blind test is shown to see brightness
//! (measured: 10% brighter fails bumps, rdgranit and bubinga; bozo passes it at 0.95 of its
//! threshold). media4 is judged against POV-Ray at converged media quadrature, as the sweep
//! judges media scenes, and must fail against POV-Ray's image as written.

use std::path::{Path, PathBuf};

use penumbra::lang::{LoadOptions, load_scene};
use penumbra::output::Image;
use penumbra::render::RenderOptions;
use penumbra::study::corpus::{self, TestKind, scan};
use penumbra::study::media_quadrature;
use penumbra::study::read_reference;

const EXAMPLES: &str = "/usr/share/povray-3.7/scenes";
const INCLUDES: &str = "/usr/share/povray-3.7/include";

/// (scene, true when its textures use POV-Ray's noise: the distribution test decides)
const SAMPLE: &[(&str, bool)] = &[
    ("language/macros/local.pov", false),
    ("language/macros/macro1.pov", false),
    ("lights/arealit1.pov", false),
    ("lights/fillite.pov", false),
    ("lights/parallel_lights.pov", false),
    ("advanced/bwstripe.pov", false),
    ("incdemo/shapes2.pov", false),
    ("objects/quartic/torus.pov", false),
    ("textures/patterns/brick.pov", false),
    ("textures/patterns/gradient.pov", false),
    ("textures/patterns/leopard.pov", false),
    ("textures/patterns/onion.pov", false),
    ("textures/patterns/radial.pov", false),
    ("interior/iortest.pov", false),
    ("interior/media/media4.pov", false),
    ("incdemo/metals/golds.pov", false),
    ("incdemo/finish.pov", false),
    ("textures/patterns/bozo.pov", true),
    ("textures/patterns/bumps.pov", true),
    ("incdemo/stones/rdgranit.pov", true),
    ("incdemo/woods/bubinga.pov", true),
];

fn replicates(path: &Path) -> Vec<Image> {
    let options = LoadOptions {
        include_paths: vec![path.parent().expect("folder").to_path_buf()],
        image_width: 160,
        image_height: 120,
        ..LoadOptions::default()
    };
    let scene = load_scene(path, &options)
        .unwrap_or_else(|d| panic!("{}: {d}", path.display()))
        .scene;
    (0..4)
        .map(|k| {
            let o = RenderOptions {
                width: 160,
                height: 120,
                samples_per_pixel: 64,
                seed: 100 + k,
                ..RenderOptions::default()
            };
            penumbra::render_scene(&scene, &o, &()).expect("renders").0
        })
        .collect()
}

/// A committed reference: POV-Ray's at converged media quadrature for scenes with media
/// (`penumbra reference --converged-media`, as the sweep renders them), `suffix` naming
/// another version.
fn reference_path(scene: &str, suffix: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/references/examples")
        .join(format!("{}{suffix}.exr", scan::flat_name(scene)))
}

/// The scene's test, from the instrument's static scan.
fn classify(path: &Path) -> TestKind {
    let files = scan::sources(path, &[PathBuf::from(INCLUDES)]).expect("readable");
    let words = scan::noise_words(&files);
    if words.is_empty() {
        TestKind::Pixel
    } else {
        TestKind::Distribution(words)
    }
}

#[test]
fn a_sample_of_the_corpus_matches_povray() {
    let mut failures = Vec::new();
    for &(scene, noisy) in SAMPLE {
        let path = Path::new(EXAMPLES).join(scene);
        if !path.exists() {
            println!("{scene}: skipped, the povray-examples package is not installed");
            continue;
        }
        let kind = classify(&path);
        if matches!(kind, TestKind::Distribution(_)) != noisy {
            failures.push(format!("{scene}: classified {kind:?}"));
            continue;
        }
        let reference = read_reference(&reference_path(scene, "")).expect("committed reference");
        let images = replicates(&path);
        let judgement = corpus::judge(&kind, &images, &reference).expect("comparable");
        println!("{scene}: {}", judgement.summary());
        if !judgement.passes() {
            failures.push(format!("{scene}: {}", judgement.summary()));
        }
        if media_quadrature::has_media(&std::fs::read(&path).expect("readable")) {
            // The reference is POV-Ray's at converged quadrature; against POV-Ray's image as
            // written (method 3, 5 samples, 6% brighter) penumbra must fail.
            let as_written = reference_path(scene, "-as-written");
            let as_written = read_reference(&as_written).expect("committed reference");
            let wrong = corpus::judge(&kind, &images, &as_written).expect("comparable");
            if wrong.passes() {
                failures.push(format!(
                    "{scene}: passes against POV-Ray's quadrature as written too: {}",
                    wrong.summary()
                ));
            }
        }
        if noisy {
            let brighter: Vec<Image> = images.iter().map(|i| i.map(|v| v * 1.2)).collect();
            let wrong = corpus::judge(&kind, &brighter, &reference).expect("comparable");
            if wrong.passes() {
                failures.push(format!(
                    "{scene}: 20% brighter still passes: {}",
                    wrong.summary()
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
