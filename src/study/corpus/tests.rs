use super::exec::{Ended, Finished};
use super::judge::distribution_test;
use super::scan::*;
use super::*;
use crate::output::Image;

#[test]
fn globs_match_whole_paths() {
    assert!(glob_match("textures/*", "textures/patterns/bozo.pov"));
    assert!(glob_match("*bozo.pov", "textures/patterns/bozo.pov"));
    assert!(glob_match(
        "t?xtures/*/b*.pov",
        "textures/patterns/bozo.pov"
    ));
    assert!(!glob_match("textures/*.inc", "textures/patterns/bozo.pov"));
    assert!(!glob_match("bozo", "textures/patterns/bozo.pov"));
    assert!(glob_match("*", ""));
}

#[test]
fn includes_outside_comments_are_found() {
    let text = "#include \"colors.inc\" // #include \"no.inc\"\n/* #include \"nor.inc\" */\n#include  \"woods.inc\"";
    assert_eq!(included_names(text), vec!["colors.inc", "woods.inc"]);
    assert_eq!(strip_comments("a /* b /* c */ d */ e"), "a  e");
    assert_eq!(strip_comments("\"//x\" y"), "\"//x\" y");
}

fn file(text: &str, local: bool) -> SourceFile {
    SourceFile {
        path: PathBuf::from(if local { "s.pov" } else { "lib.inc" }),
        text: text.to_string(),
        local,
    }
}

#[test]
fn noise_is_found_through_library_declarations() {
    let library = file(
        "#declare T_Wood = texture { pigment { wood turbulence 0.1 } }\n\
         #declare T_Plain = texture { pigment { rgb 1 } }\n\
         #declare T_Both = texture { T_Wood }\n\
         #macro M() #if (1) pigment { bozo } #end #end",
        false,
    );
    let uses = |scene: &str| noise_words(&[file(scene, true), library.clone()]);
    assert!(uses("sphere { 0, 1 texture { T_Plain } }").is_empty());
    assert_eq!(uses("sphere { 0, 1 texture { T_Both } }"), vec!["T_Both"]);
    assert_eq!(uses("sphere { 0, 1 M() }"), vec!["M"]);
    assert_eq!(uses("plane { y, 0 pigment { granite } }"), vec!["granite"]);
    assert!(uses("// granite\nplane { y, 0 pigment { checker } }").is_empty());
    // The library's own words do not count: only what the scene names.
    assert!(noise_words(std::slice::from_ref(&library)).is_empty());
}

#[test]
fn inis_give_the_first_frame() {
    let dir = TempDir::new("corpus-test").expect("temp dir");
    let ini = dir.path().join("a.ini");
    std::fs::write(
        &ini,
        "; comment\nInput_File_Name=A.pov\nInitial_Frame = 3 ; x\nFinal_Frame=9\n",
    )
    .expect("ini");
    std::fs::write(dir.path().join("b.pov"), "").expect("scene");
    std::fs::write(dir.path().join("A.pov"), "").expect("scene");
    assert_eq!(
        ini_value("x=1\nInitial_Frame = 3 ; y", "initial_frame"),
        Some("3".into())
    );
    assert_eq!(ini_for(&dir.path().join("A.pov")), Some(ini.clone()));
    assert_eq!(ini_for(&dir.path().join("b.pov")), None);
    assert_eq!(
        ini_args(&ini),
        vec![ini.display().to_string(), "+SF3".into(), "+EF3".into()]
    );
    // Frames as switches on a line (animations/splinefollow.ini), or not at all.
    let switches = dir.path().join("c.ini");
    std::fs::write(
        &switches,
        "Antialias=On\n+kf0.1666 +kff20 +kc declare=fp=0\n",
    )
    .expect("ini");
    assert_eq!(first_frame_args(&switches), vec!["+SF1", "+EF1"]);
    std::fs::write(&switches, "+KFI4 +KFF9\n").expect("ini");
    assert_eq!(first_frame_args(&switches), vec!["+SF4", "+EF4"]);
    std::fs::write(&switches, "Antialias=On\n+kf0.5 ; +kff20\n").expect("ini");
    assert!(first_frame_args(&switches).is_empty());
}

#[test]
fn the_cache_key_follows_content_size_k_and_version() {
    let files = [file("sphere {0, 1}", true), file("#declare A = 1;", false)];
    let key = ReferenceKey {
        files: &files,
        width: 160,
        height: 120,
        supersample: 16,
        povray_version: "POV-Ray 3.7.0.10",
        extra_args: &[],
        media: MediaQuadrature::AsWritten,
    };
    let name = key.file_name("a/b.pov");
    assert!(name.starts_with("a_b-") && name.ends_with(".exr"), "{name}");
    assert_eq!(name, key.clone().file_name("a/b.pov"));
    let other_files = [file("sphere {0, 2}", true), files[1].clone()];
    let changed = [
        ReferenceKey {
            files: &other_files,
            ..key.clone()
        },
        ReferenceKey {
            supersample: 8,
            ..key.clone()
        },
        ReferenceKey {
            width: 80,
            ..key.clone()
        },
        ReferenceKey {
            povray_version: "POV-Ray 3.8",
            ..key.clone()
        },
        ReferenceKey {
            media: MediaQuadrature::Converged,
            ..key.clone()
        },
    ];
    for k in &changed {
        assert_ne!(k.file_name("a/b.pov"), name);
    }
}

#[test]
fn parse_outcomes_are_sorted_like_check_all() {
    let run = |ended: Ended, stderr: &str| Finished {
        ended,
        stderr: stderr.to_string(),
        seconds: 0.1,
    };
    assert_eq!(parse_status(&run(Ended::Success, "")), ParseStatus::Parsed);
    assert_eq!(
        parse_status(&run(Ended::TimedOut, "")),
        ParseStatus::TimedOut
    );
    let failed = || Ended::Failed("exit status: 1".into());
    assert!(matches!(
        parse_status(&run(failed(), "error: unsupported feature `text`\n --> a.pov:3")),
        ParseStatus::Unsupported(m) if m.contains("text")
    ));
    assert!(matches!(
        parse_status(&run(failed(), "thread 'main' panicked at src/x.rs:1:1:\nboom")),
        ParseStatus::Crash(m) if m.contains("boom")
    ));
    assert!(matches!(
        parse_status(&run(failed(), "error: undeclared identifier")),
        ParseStatus::Error(_)
    ));
}

/// Deterministic value noise in [0, 1): a hash of integer lattice points, interpolated.
fn value_noise(x: f64, y: f64, seed: u64) -> f64 {
    let hash = |i: i64, j: i64| {
        let mut h = (i as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15)
            ^ (j as u64).wrapping_mul(0xc2b2_ae3d_27d4_eb4f)
            ^ seed.wrapping_mul(0x1656_67b1_9e37_79f9);
        h ^= h >> 29;
        h = h.wrapping_mul(0xbf58_476d_1ce4_e5b9);
        h ^= h >> 32;
        (h >> 11) as f64 / (1u64 << 53) as f64
    };
    let (i, j) = (x.floor() as i64, y.floor() as i64);
    let (fx, fy) = (x - x.floor(), y - y.floor());
    let (sx, sy) = (fx * fx * (3.0 - 2.0 * fx), fy * fy * (3.0 - 2.0 * fy));
    let top = hash(i, j) + sx * (hash(i + 1, j) - hash(i, j));
    let bottom = hash(i, j + 1) + sx * (hash(i + 1, j + 1) - hash(i, j + 1));
    top + sy * (bottom - top)
}

/// A scene-like image: a dark background, a "marble" rectangle whose texture depends on the
/// noise phase `seed`, brightened by `gain` and shifted by `offset`; plus per-pixel noise
/// of standard deviation `sigma` drawn with `noise_seed`.
fn textured(seed: u64, gain: f32, offset: f32, sigma: f64, noise_seed: u64) -> Image {
    textured_at(2.5, seed, gain, offset, sigma, noise_seed)
}

/// As `textured`, with noise cells of `cell` pixels.
fn textured_at(cell: f64, seed: u64, gain: f32, offset: f32, sigma: f64, noise_seed: u64) -> Image {
    Image::from_fn(160, 120, |x, y| {
        let (fx, fy) = (x as f64, y as f64);
        let inside = (20..140).contains(&x) && (30..110).contains(&y);
        let base = if inside {
            0.2 + 0.6 * value_noise(fx / cell, fy / cell, seed)
        } else {
            0.05 + 0.1 * fy / 120.0
        };
        let n = sigma * (value_noise(fx * 7.31, fy * 3.17, noise_seed) - 0.5) * 3.46;
        let v = (base * f64::from(gain) + f64::from(offset) + n) as f32;
        [v, v * 0.8, v * 0.6]
    })
}

#[test]
fn the_distribution_test_is_blind_to_the_noise_phase_only() {
    let reference = textured(1, 1.0, 0.0, 0.0, 0);
    let half = textured(1, 1.0, 0.0, 0.002, 99);
    let replicates = |seed: u64, gain: f32, offset: f32| -> Vec<Image> {
        (0..4)
            .map(|k| textured(seed, gain, offset, 0.05, 10 + k))
            .collect()
    };
    for phase in [2, 3, 4] {
        let v = distribution_test(&replicates(phase, 1.0, 0.0), &reference, &half).expect("ok");
        assert!(v.passes(), "another phase must pass: {v}");
        let pixel =
            crate::study::evaluate(&replicates(phase, 1.0, 0.0), &reference, &half).expect("ok");
        assert!(
            !pixel.passes(crate::study::SQRT_B_THRESHOLD),
            "the pixel test sees it"
        );
    }
    for (gain, offset) in [(1.2, 0.0), (0.8, 0.0), (1.0, 0.05), (1.0, -0.05)] {
        let v = distribution_test(&replicates(2, gain, offset), &reference, &half).expect("ok");
        assert!(!v.passes(), "gain {gain} offset {offset} must fail: {v}");
    }
    // A missing object: the rectangle's right half is background.
    let mut missing = replicates(2, 1.0, 0.0);
    for image in &mut missing {
        for y in 30..110 {
            for x in 80..140 {
                image.set(x, y, [0.08, 0.064, 0.048]);
            }
        }
    }
    let v = distribution_test(&missing, &reference, &half).expect("ok");
    assert!(!v.passes(), "a missing half must fail: {v}");
    assert!(distribution_test(&missing[..1], &reference, &half).is_err());
    // Coarse noise (8-pixel cells) moves block statistics more with its phase: the test
    // widens (contrast 0.6 in 8-pixel cells: a 25% gain passes), still passes another phase
    // and still sees a 40% gain.
    let coarse = |seed: u64, gain: f32| -> Vec<Image> {
        (0..4)
            .map(|k| textured_at(8.0, seed, gain, 0.0, 0.05, 10 + k))
            .collect()
    };
    let reference = textured_at(8.0, 1, 1.0, 0.0, 0.0, 0);
    let v = distribution_test(&coarse(2, 1.0), &reference, &half).expect("ok");
    assert!(v.passes(), "coarse noise, another phase: {v}");
    let v = distribution_test(&coarse(2, 1.4), &reference, &half).expect("ok");
    assert!(!v.passes(), "coarse noise, 40% gain: {v}");
}

#[test]
fn cheap_scenes_come_first() {
    let costs = vec![(0, 3.0), (1, 0.5), (2, f64::INFINITY), (3, 0.5), (4, 0.0)];
    assert_eq!(sorted_by_cost(costs), vec![4, 1, 3, 0, 2]);
}

#[test]
fn the_report_has_every_row_and_the_counts() {
    let req = CorpusRequest {
        scenes_dir: PathBuf::from("/scenes"),
        include_dirs: Vec::new(),
        only: None,
        seeds: 4,
        spp: 64,
        width: 160,
        height: 120,
        supersample: 16,
        out: PathBuf::from("docs/corpus.md"),
        cache: PathBuf::from("/cache"),
        penumbra: PathBuf::from("penumbra"),
        timeouts: Timeouts::default(),
        cheap_first: true,
        known: Vec::new(),
        phase_ensemble: Vec::new(),
    };
    let mut rows = vec![
        Row::new("a/parsed.pov"),
        Row::new("a/unsupported.pov"),
        Row::new("b/broken.pov"),
        Row::new("c/explained.pov"),
    ];
    rows[3].parse = ParseStatus::Parsed;
    rows[3].outcome = Outcome::RenderFailed("penumbra failed".into());
    rows[3].known = Some("a feature not yet supported".into());
    rows[0].parse = ParseStatus::Parsed;
    rows[1].parse = ParseStatus::Unsupported("error: unsupported: `text` | x".into());
    rows[2].parse = ParseStatus::Parsed;
    rows[2].outcome = Outcome::RenderFailed("penumbra panicked: boom".into());
    let context = report::Context {
        req: &req,
        povray_version: "POV-Ray 3.7",
        start: std::time::Instant::now(),
    };
    let text = report::markdown(&context, &rows, false);
    assert!(
        text.contains("| a/parsed.pov | yes | pixel | not measured yet |"),
        "{text}"
    );
    assert!(text.contains("`text` \\| x"), "pipes are escaped: {text}");
    assert!(
        text.contains("| b/broken.pov | yes | pixel | penumbra failed | penumbra panicked: boom")
    );
    assert!(text.contains("| parse | 3 |") && text.contains("| penumbra failed to render | 2 |"));
    assert!(
        text.contains("| fail, with the reason written down | 1 |"),
        "{text}"
    );
    assert!(text.contains("| fail, unexplained | 1 |"), "{text}");
    assert!(
        text.contains("a feature not yet supported; penumbra failed"),
        "{text}"
    );
    assert!(text.contains("interrupted or still running"));
}
