use std::path::{Path, PathBuf};

use super::*;
use crate::lang::MemoryFiles;

fn args(line: &str) -> Vec<String> {
    line.split_whitespace().map(str::to_string).collect()
}

fn read(line: &str) -> Result<PovSettings, PovArgError> {
    parse_args(&args(line), &MemoryFiles::default())
}

#[test]
fn switches_set_size_output_and_antialiasing() {
    let s = read("scene.pov +W640 +H480 +A0.1 +AM2 +R4 +Oout.png -D +WT2 +FN16").unwrap();
    assert_eq!(s.input, Some(PathBuf::from("scene.pov")));
    assert_eq!((s.width, s.height), (640, 480));
    assert_eq!(s.output, Some(PathBuf::from("out.png")));
    assert_eq!(
        s.antialias,
        Antialias {
            on: true,
            threshold: 0.1,
            method: 2,
            depth: 4
        }
    );
    assert_eq!(s.threads, Some(2));
    assert_eq!((s.file_type, s.bits_per_colour), ('N', 16));
    assert!(s.notes.is_empty(), "{:?}", s.notes);
}

#[test]
fn longest_switch_wins_and_case_does_not_matter() {
    let s = read("+iscene.pov +kfi2 +KFF30 +KI0.5 +KF2 +SF3 +EF0.5 +KC").unwrap();
    assert_eq!(s.input, Some(PathBuf::from("scene.pov")));
    let a = s.animation;
    assert_eq!((a.initial_frame, a.final_frame), (2, 30));
    assert_eq!((a.initial_clock, a.final_clock), (0.5, 2.0));
    assert_eq!(a.subset_start, Some(Bound::Pixel(3)));
    assert_eq!(a.subset_end, Some(Bound::Fraction(0.5)));
    assert!(a.cyclic);
}

#[test]
fn display_and_pause_are_notes_not_errors() {
    let s = read("s.pov +D +P +X -GA").unwrap();
    assert_eq!(s.notes.len(), 4, "{:?}", s.notes);
    assert!(s.notes[0].contains("+D"), "{}", s.notes[0]);
    assert!(read("s.pov -D -P").unwrap().notes.is_empty());
}

#[test]
fn unknown_switch_names_the_nearest() {
    let e = read("s.pov +Y640").unwrap_err();
    assert!(e.message.contains("`+Y640`"), "{e}");
    assert!(e.message.contains("nearest known"), "{e}");
    let e = read("s.pov Widht=640").unwrap_err();
    assert!(e.message.contains("Width"), "{e}");
    let e = read("s.pov +Wabc").unwrap_err();
    assert!(e.message.contains("not a number"), "{e}");
}

#[test]
fn ini_sections_comments_and_positioned_errors() {
    let text = "; comment\nWidth=320 ; trailing\nHeight=200\n[low]\nWidth=80\n\
                Antialias=On\n[high]\nWidth=1600\n+A0.1 -J\n";
    let files = MemoryFiles::default();
    let s = parse_ini_text(Path::new("r.ini"), text, None, &files).unwrap();
    assert_eq!((s.width, s.height), (320, 200));
    assert!(!s.antialias.on);
    let s = parse_ini_text(Path::new("r.ini"), text, Some("high"), &files).unwrap();
    assert_eq!((s.width, s.height), (1600, 200));
    assert_eq!(s.antialias.threshold, 0.1);
    let e = parse_ini_text(Path::new("r.ini"), "Width=1\nQuality=12\n", None, &files).unwrap_err();
    assert_eq!(e.place, Some((PathBuf::from("r.ini"), 2)));
    assert!(e.to_string().starts_with("r.ini:2: "), "{e}");
}

#[test]
fn ini_files_on_the_command_line_and_inside_ini_files() {
    let mut files = MemoryFiles::default();
    files.files.insert(
        PathBuf::from("a.ini"),
        "Input_File_Name=x.pov\nres\n".into(),
    );
    files
        .files
        .insert(PathBuf::from("res.ini"), "Width=120\nHeight=90\n".into());
    files.files.insert(
        PathBuf::from("q.ini"),
        "[160x120, No AA]\nWidth=160\nHeight=120\n".into(),
    );
    let s = parse_args(&args("a.ini +W100"), &files).unwrap();
    assert_eq!(s.input, Some(PathBuf::from("x.pov")));
    assert_eq!((s.width, s.height), (100, 90));
    let s = parse_args(&["q.ini[160x120, No AA]".to_string()], &files).unwrap();
    assert_eq!((s.width, s.height), (160, 120));
    let e = parse_args(&args("missing.ini"), &files).unwrap_err();
    assert!(e.message.contains("missing.ini"), "{e}");
}

#[test]
fn declares_and_library_paths() {
    let s = read("s.pov Declare=Speed=2.5 +L/inc Library_Path=/other").unwrap();
    assert_eq!(s.declares, vec![("Speed".to_string(), 2.5)]);
    assert_eq!(
        s.library_paths,
        vec![PathBuf::from("/inc"), PathBuf::from("/other")]
    );
    assert!(read("s.pov Declare=1x=2").is_err());
}

#[test]
fn frames_are_named_and_clocked_as_povray_does() {
    let j = job::job(&read("scene.pov +KFI1 +KFF30").unwrap()).unwrap();
    assert_eq!(j.frames.len(), 30);
    assert_eq!(j.frames[0].output, PathBuf::from("scene01.png"));
    assert_eq!(j.frames[29].output, PathBuf::from("scene30.png"));
    assert_eq!(j.frames[29].clock.clock, 1.0);
    assert_eq!(j.frames[0].clock.clock, 0.0);
    assert!(j.frames[0].clock.clock_on);
    let j = job::job(&read("scene.pov +KFF3 +Oout/ +FE").unwrap()).unwrap();
    let names: Vec<_> = j.frames.iter().map(|f| f.output.clone()).collect();
    assert_eq!(
        names,
        ["out/scene1.exr", "out/scene2.exr", "out/scene3.exr"].map(PathBuf::from)
    );
    let j = job::job(&read("s.pov +KFI0 +KFF10 +SF3 +EF4 +KC +Oa.png").unwrap()).unwrap();
    let frames: Vec<_> = j.frames.iter().map(|f| (f.number, f.clock.clock)).collect();
    assert_eq!(frames, vec![(3, 3.0 / 11.0), (4, 4.0 / 11.0)]);
    assert_eq!(j.frames[0].output, PathBuf::from("a03.png"));
    let j = job::job(&read("s.pov --frames 2..4").unwrap()).unwrap();
    assert_eq!(j.frames.len(), 3);
    let still = job::job(&read("s.pov +K0.25").unwrap()).unwrap();
    assert_eq!(still.frames.len(), 1);
    assert_eq!(still.frames[0].clock.clock, 0.25);
    assert_eq!(still.frames[0].output, PathBuf::from("s.png"));
}

#[test]
fn windows_in_pixels_and_fractions() {
    let j = job::job(&read("s.pov +W100 +H80 +SR0.5 +ER0.75 +SC10 +EC30").unwrap()).unwrap();
    let w = j.window.unwrap();
    assert_eq!((w.x, w.y), (9..30, 40..60));
    assert!(job::job(&read("s.pov +SR50 +ER10").unwrap()).is_err());
    // A plain 1 ends at the last column or row, as in POV-Ray; 2 is a pixel.
    let j = job::job(&read("s.pov +W100 +H80 +SC1 +EC1 +ER1").unwrap()).unwrap();
    assert!(j.window.is_none_or(|w| (w.x, w.y) == (0..100, 0..80)));
    let w = job::job(&read("s.pov +W100 +H80 +EC2").unwrap())
        .unwrap()
        .window
        .unwrap();
    assert_eq!((w.x, w.y), (0..2, 0..80));
}

#[test]
fn antialiasing_maps_to_more_samples_for_stricter_settings() {
    let off = sampling_for(&Antialias::default());
    let on = sampling_for(&Antialias {
        on: true,
        ..Antialias::default()
    });
    let strict = sampling_for(&Antialias {
        on: true,
        threshold: 0.05,
        method: 2,
        depth: 4,
    });
    assert!(off.spp <= on.spp && on.spp < strict.spp);
    // Both adaptive, as every count from 2 on is (crate::render::adaptive_by_default).
    assert!(on.adaptive && off.adaptive);
}

#[test]
fn looks_like_povray_recognises_invocations() {
    for a in [
        "+W640",
        "-D",
        "scene.pov",
        "render.ini",
        "Width=3",
        "q.ini[x]",
    ] {
        assert!(looks_like_povray(a), "{a}");
    }
    for a in ["render", "--help", "check", "-", "x=y"] {
        assert!(!looks_like_povray(a), "{a}");
    }
}

#[test]
fn penumbras_own_options_mix_with_switches() {
    let s = read("scene.pov +SF1 +EF1 --spp 64 --seed 101 --quiet --allow-write out/").unwrap();
    assert_eq!((s.spp, s.seed, s.quiet), (Some(64.0), 101, true));
    assert_eq!(s.allow_write, Some(PathBuf::from("out/")));
    assert_eq!(read("scene.pov").unwrap().allow_write, None);
}

/// `--spp 1.5` is an adaptive render's average, sampled adaptively by default; uniform
/// sampling refuses it, and counts below one sample are refused as they are read.
#[test]
fn a_fractional_spp_is_an_adaptive_average() {
    let sampling = |line: &str| job::job(&read(line).unwrap()).map(|j| j.sampling);
    let half = sampling("scene.pov --spp 1.5").unwrap();
    assert_eq!(
        (half.spp, half.average, half.adaptive),
        (2, Some(1.5), true)
    );
    let whole = sampling("scene.pov --spp 2").unwrap();
    assert_eq!((whole.spp, whole.average), (2, None));
    assert!(sampling("scene.pov --spp 1.5 --uniform").is_err());
    assert!(read("scene.pov --spp 0.5").is_err());
    // `render --spp` reaches the job without the option table's check.
    let settings = |spp: f64| PovSettings {
        spp: Some(spp),
        ..read("scene.pov").unwrap()
    };
    for bad in [0.0, -2.0, f64::NAN, 1e30] {
        assert!(job::job(&settings(bad)).is_err(), "{bad}");
    }
}

#[test]
fn an_empty_output_name_means_the_default() {
    // advanced/benchmark/benchmark.ini writes `Output_File_Name=` for the scene's own name.
    let files = MemoryFiles::default();
    let text = "Output_File_Name=x.png\nOutput_File_Name=\nHigh_Reproducibility=off\n";
    let s = parse_ini_text(Path::new("b.ini"), text, None, &files).unwrap();
    assert_eq!(s.output, None);
}
