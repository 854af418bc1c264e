//! Animation: frame k of scenes/clock_animation.pov (+KFI1 +KFF5), with the clock POV-Ray's
//! options give it, passes the statistical test against POV-Ray's frame k
//! (shared/testing-statistics.md: K = 4 seeds, N = 64, 160x120, sqrt(B) <= 0.005, no failing
//! tile). The reference is POV-Ray's render at that frame's clock (+K0.75, see
//! tests/references/regenerate.sh). A window of a render holds exactly the full render's
//! pixels, with adaptive sampling too.

use std::path::PathBuf;

use penumbra::lang::{LoadOptions, MemoryFiles, load_scene};
use penumbra::povray_args::{job::job, parse_args};
use penumbra::render::{PixelWindow, PreparedScene, RenderOptions, render};
use penumbra::study::{self, SQRT_B_THRESHOLD};

const FRAME: usize = 4;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn frame_scene(frame: usize) -> (penumbra::scene::Scene, f64) {
    let scene = root().join("scenes/clock_animation.pov");
    let args: Vec<String> = [
        scene.to_str().expect("utf-8"),
        "+KFI1",
        "+KFF5",
        "+W160",
        "+H120",
    ]
    .map(str::to_string)
    .to_vec();
    let job = job(&parse_args(&args, &MemoryFiles::default()).expect("parses")).expect("job");
    assert_eq!(job.frames.len(), 5);
    let f = &job.frames[frame - 1];
    assert_eq!(f.number, frame as i64);
    assert_eq!(
        f.output,
        PathBuf::from(format!("clock_animation{frame}.png"))
    );
    let options = LoadOptions {
        image_width: 160,
        image_height: 120,
        clock: f.clock,
        ..LoadOptions::default()
    };
    let loaded = load_scene(&scene, &options).expect("loads");
    (loaded.scene, f.clock.clock)
}

fn renders(scene: &penumbra::scene::Scene, spp: u32, seeds: u64) -> Vec<penumbra::output::Image> {
    (0..seeds)
        .map(|k| {
            let o = RenderOptions {
                width: 160,
                height: 120,
                samples_per_pixel: spp,
                seed: 100 + k,
                ..RenderOptions::default()
            };
            penumbra::render_scene(scene, &o, &()).expect("renders").0
        })
        .collect()
}

#[test]
fn animation_frame_converges_to_povrays_frame() {
    let reference = root().join(format!("tests/references/clock_animation_frame{FRAME}.exr"));
    let reference = study::read_reference(&reference).expect("committed reference");
    let (scene, clock) = frame_scene(FRAME);
    assert_eq!(clock, 0.75);
    let v = study::evaluate(&renders(&scene, 64, 4), &reference.full, &reference.half)
        .expect("comparable");
    println!("clock_animation frame {FRAME} (clock {clock}): {v}");
    assert!(v.passes(SQRT_B_THRESHOLD), "{v}");
    // The clock matters: frame 1 is far from frame 4's reference.
    let (first, _) = frame_scene(1);
    let v1 = study::evaluate(&renders(&first, 16, 2), &reference.full, &reference.half)
        .expect("comparable");
    println!("clock_animation frame 1 against frame {FRAME}'s reference: {v1}");
    assert!(!v1.passes(SQRT_B_THRESHOLD), "{v1}");
}

#[test]
fn a_window_holds_exactly_the_full_renders_pixels() {
    let (scene, _) = frame_scene(2);
    let prepared = PreparedScene::new(&scene);
    for adaptive in [false, true] {
        let options = RenderOptions {
            width: 48,
            height: 36,
            samples_per_pixel: 8,
            adaptive,
            ..RenderOptions::default()
        };
        let (full, _) = render(&prepared, &options, &()).expect("full");
        let window = PixelWindow {
            x: 5..29,
            y: 17..36,
        };
        let windowed = RenderOptions {
            window: Some(window.clone()),
            ..options
        };
        let (part, _) = render(&prepared, &windowed, &()).expect("window");
        for (i, (a, b)) in full.pixels.iter().zip(&part.pixels).enumerate() {
            let (x, y) = (i % 48, i / 48);
            if window.contains(x, y) {
                assert_eq!(a, b, "adaptive {adaptive}: pixel ({x}, {y})");
            } else {
                assert_eq!(b.count, 0, "adaptive {adaptive}: pixel ({x}, {y}) rendered");
            }
        }
        println!("adaptive {adaptive}: window {window:?} equals the full render exactly");
    }
}

/// The render-ready scene is rebuilt for a frame only when its scene changed.
#[test]
fn frames_rebuild_the_scene_only_when_it_changes() {
    for (name, expected) in [
        ("clock_animation.pov", [true, true, true]),
        ("checker.pov", [true, false, false]),
    ] {
        let scene = root().join("scenes").join(name);
        let args: Vec<String> = [
            scene.to_str().expect("utf-8"),
            "+KFF3",
            "+W8",
            "+H6",
            "--spp",
            "1",
        ]
        .map(str::to_string)
        .to_vec();
        let mut job =
            job(&parse_args(&args, &MemoryFiles::default()).expect("parses")).expect("job");
        job.write = false;
        let settings = penumbra::render_job::JobSettings::default();
        let reports = penumbra::render_job::run_job(&job, &settings, &()).expect("renders");
        let rebuilt: Vec<bool> = reports.iter().map(|r| r.rebuilt).collect();
        println!("{name}: rebuilt {rebuilt:?}");
        assert_eq!(rebuilt, expected, "{name}");
    }
}

/// `--motion-blur N` splits a frame's samples over N times of its shutter: a scene that does
/// not move renders exactly as without it (sampled uniformly, as motion blur is), and one
/// that moves does not.
#[test]
fn motion_blur_spreads_the_samples_over_the_shutter() {
    for (name, same) in [("checker.pov", true), ("clock_animation.pov", false)] {
        let scene = root().join("scenes").join(name);
        let render = |blur: &str| {
            let args: Vec<String> = [
                scene.to_str().expect("utf-8"),
                "+KFF3",
                "+W16",
                "+H12",
                "--spp",
                "8",
                "--motion-blur",
                blur,
                "--uniform",
            ]
            .map(str::to_string)
            .to_vec();
            let mut job =
                job(&parse_args(&args, &MemoryFiles::default()).expect("parses")).expect("job");
            job.write = false;
            job.frames.truncate(1);
            penumbra::render_job::render_frame_film(&job, &job.frames[0], &()).expect("renders")
        };
        let (sharp, blurred) = (render("1"), render("4"));
        assert_eq!(sharp.pixels == blurred.pixels, same, "{name}");
        println!("{name}: motion blur changes the frame: {}", !same);
    }
}
