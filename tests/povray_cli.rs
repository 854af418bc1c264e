//! POV-Ray-style command lines and INI files run through the `penumbra` binary: the image
//! sizes, names and frames they produce, one INI file taken as is from POV-Ray's own ini
//! folder, notes for options that do not apply, errors for unknown ones, and partial
//! renders that equal the same window of the full render byte for byte.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const SYSTEM_INI: &str = "/usr/share/povray-3.7/ini";

fn scene(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

/// A fresh, empty folder for one test's output.
fn workdir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("penumbra-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn penumbra(dir: &Path, args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_penumbra"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("runs penumbra");
    println!(
        "$ penumbra {}\n{}",
        args.join(" "),
        String::from_utf8_lossy(&out.stderr).trim_end()
    );
    out
}

fn succeeds(dir: &Path, args: &[&str]) -> String {
    let out = penumbra(dir, args);
    assert!(out.status.success(), "penumbra {args:?} failed");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn size(path: &Path) -> (u32, u32) {
    image::image_dimensions(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("lists")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn povray_command_lines_set_size_and_name() {
    let dir = workdir("switches");
    let checker = scene("checker.pov");
    let c = checker.to_str().expect("utf-8");
    succeeds(&dir, &[c, "+W64", "+H48", "+A0.3", "+Oout.png", "-D"]);
    assert_eq!(size(&dir.join("out.png")), (64, 48));
    succeeds(&dir, &[&format!("+I{c}"), "+W40", "+H30", "-A", "+FN16"]);
    assert_eq!(size(&dir.join("checker.png")), (40, 30));
    succeeds(&dir, &["render", c, "+W24", "+H18", "+Orender", "+FE"]);
    assert!(dir.join("render.exr").is_file(), "{:?}", files(&dir));
    succeeds(
        &dir,
        &[
            c,
            "Width=32",
            "Height=20",
            "Output_File_Name=kv.png",
            "--spp",
            "2",
        ],
    );
    assert_eq!(size(&dir.join("kv.png")), (32, 20));
}

#[test]
fn ini_files_with_sections_and_comments() {
    let dir = workdir("ini");
    let checker = scene("checker.pov");
    let ini = format!(
        "; a render-farm job template\n\
         Input_File_Name={}\n\
         Output_File_Name=job.png   ; trailing comment\n\
         Width=50\nHeight=40\nAntialias=On\nAntialias_Threshold=0.3\nSampling_Method=2\n\
         Antialias_Depth=2\nQuality=9\nPause_When_Done=Off\n\
         [small]\nWidth=20\nHeight=16\n\
         [anim]\nInitial_Frame=1\nFinal_Frame=3\nInitial_Clock=0\nFinal_Clock=1\n",
        checker.display()
    );
    std::fs::write(dir.join("job.ini"), ini).expect("ini");
    succeeds(&dir, &["job.ini"]);
    assert_eq!(size(&dir.join("job.png")), (50, 40));
    succeeds(&dir, &["job.ini[small]", "+Osmall.png"]);
    assert_eq!(size(&dir.join("small.png")), (20, 16));
    succeeds(&dir, &["job.ini[anim]", "+W8", "+H6", "+Oframe.png"]);
    for f in ["frame1.png", "frame2.png", "frame3.png"] {
        assert_eq!(size(&dir.join(f)), (8, 6), "{f}");
    }
    std::fs::write(dir.join("bad.ini"), "Width=20\n\nQualty=3\n").expect("ini");
    let out = penumbra(&dir, &["bad.ini", checker.to_str().expect("utf-8")]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(err.contains("bad.ini:3:"), "{err}");
    assert!(err.contains("Quality"), "{err}");
}

#[test]
fn ini_files_from_povrays_own_folder() {
    if !Path::new(SYSTEM_INI).is_dir() {
        println!("skipped: {SYSTEM_INI} is not installed");
        return;
    }
    let dir = workdir("system-ini");
    let checker = scene("checker.pov");
    let c = checker.to_str().expect("utf-8");
    // res120.ini as is (Width=120, Height=90), named by its path, then by its bare name as
    // POV-Ray finds it in its ini folder; low.ini adds Quality=4.
    succeeds(
        &dir,
        &[
            c,
            &format!("{SYSTEM_INI}/res120.ini"),
            "+Ores.png",
            "--spp",
            "2",
        ],
    );
    assert_eq!(size(&dir.join("res.png")), (120, 90));
    succeeds(&dir, &[c, "low", "+Olow.png", "--spp", "2"]);
    assert_eq!(size(&dir.join("low.png")), (120, 90));
    // quickres.ini: without a section POV-Ray reads none of its sections (800 x 600); a
    // section is chosen with file.ini[label].
    let section = format!("{SYSTEM_INI}/quickres.ini[160x120, No AA]");
    succeeds(&dir, &[c, &section, "+Oquick.png", "--spp", "1"]);
    assert_eq!(size(&dir.join("quick.png")), (160, 120));
}

#[test]
fn animation_frames_are_named_as_povray_names_them() {
    let dir = workdir("frames");
    let anim = scene("clock_animation.pov");
    let a = anim.to_str().expect("utf-8");
    let tiny = ["+W8", "+H6", "--spp", "1", "-D"];
    let run = |extra: &[&str]| succeeds(&dir, &[&[a][..], &tiny, extra].concat());
    run(&["+KFI1", "+KFF12", "+Otwelve/"]);
    let expected: Vec<String> = (1..=12)
        .map(|k| format!("clock_animation{k:02}.png"))
        .collect();
    assert_eq!(files(&dir.join("twelve")), expected);
    run(&["+KFF3", "+Othree/"]);
    let expected: Vec<String> = (1..=3).map(|k| format!("clock_animation{k}.png")).collect();
    assert_eq!(files(&dir.join("three")), expected);
    run(&["+KFI0", "+KFF10", "+SF3", "+EF4", "+KC", "+Osubset/"]);
    assert_eq!(
        files(&dir.join("subset")),
        ["clock_animation03.png", "clock_animation04.png"]
    );
    succeeds(
        &dir,
        &[
            "render", a, "--width", "8", "--height", "6", "--spp", "1", "--frames", "1..5",
        ],
    );
    for k in 1..=5 {
        assert_eq!(size(&dir.join(format!("clock_animation{k}.png"))), (8, 6));
    }
}

#[test]
fn options_that_do_not_apply_are_notes_and_unknown_ones_errors() {
    let dir = workdir("notes");
    let checker = scene("checker.pov");
    let c = checker.to_str().expect("utf-8");
    let err = succeeds(&dir, &[c, "+W8", "+H6", "+D", "+P", "+GA", "--spp", "1"]);
    let notes: Vec<&str> = err.lines().filter(|l| l.starts_with("note:")).collect();
    assert_eq!(notes.len(), 3, "{err}");
    let out = penumbra(&dir, &[c, "+W8", "+KFZ3"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(err.contains("`+KFZ3`"), "{err}");
    let out = penumbra(&dir, &[c, "+Y8"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        err.contains("unknown switch `+Y8` (nearest known:"),
        "{err}"
    );
}

#[test]
fn partial_renders_equal_the_full_render_in_their_window() {
    let dir = workdir("window");
    let s = scene("soft_shadow.pov");
    let s = s.to_str().expect("utf-8");
    let common = [s, "+W64", "+H48", "--spp", "4", "+FN16"];
    succeeds(&dir, &[&common[..], &["+Ofull.png"]].concat());
    let window = ["+SR0.25", "+ER30", "+SC9", "+EC0.75"];
    succeeds(&dir, &[&common[..], &window, &["+Opart.png"]].concat());
    succeeds(
        &dir,
        &[&common[..], &window, &["+Ocrop.png", "--crop"]].concat(),
    );
    let (full, part, crop) = (
        image::open(dir.join("full.png")).expect("full").to_rgb16(),
        image::open(dir.join("part.png")).expect("part").to_rgb16(),
        image::open(dir.join("crop.png")).expect("crop").to_rgb16(),
    );
    // Rows 13..30 and columns 9..48 (pixels from 1, ends inclusive; 0.25 of 48 rows starts
    // at row 12 from 0).
    let (xs, ys) = (8..48u32, 12..30u32);
    assert_eq!(part.dimensions(), (64, 48));
    assert_eq!(crop.dimensions(), (xs.len() as u32, ys.len() as u32));
    for y in 0..48 {
        for x in 0..64 {
            let inside = xs.contains(&x) && ys.contains(&y);
            let expected = if inside {
                *full.get_pixel(x, y)
            } else {
                image::Rgb([0, 0, 0])
            };
            assert_eq!(*part.get_pixel(x, y), expected, "pixel ({x}, {y})");
            if inside {
                assert_eq!(
                    crop.get_pixel(x - xs.start, y - ys.start),
                    full.get_pixel(x, y)
                );
            }
        }
    }
    println!("window {xs:?} x {ys:?}: byte for byte equal to the full render");
}
