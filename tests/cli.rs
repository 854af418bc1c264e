//! The command line as a user meets it: output files, determinism across thread counts, and
//! errors that point at the source.

use penumbra::study::TempDir;
use std::process::Command;

fn penumbra() -> Command {
    Command::new(env!("CARGO_BIN_EXE_penumbra"))
}

/// A fresh folder, removed when the test ends (passed or failed).
fn scratch(name: &str) -> TempDir {
    TempDir::new(&format!("cli-{name}")).expect("temp dir")
}

fn scene(name: &str) -> String {
    format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn one_and_two_threads_give_byte_identical_exr() {
    let temp = scratch("threads");
    let dir = temp.path();
    let mut outputs = Vec::new();
    for threads in [1, 2] {
        let out = dir.join(format!("t{threads}.exr"));
        let status = penumbra()
            .args([
                "render",
                &scene("soft_shadow.pov"),
                "--quiet",
                "--width",
                "64",
            ])
            .args(["--height", "48", "--spp", "8", "--seed", "7", "--threads"])
            .arg(threads.to_string())
            .arg("--output")
            .arg(&out)
            .status()
            .expect("runs");
        assert!(status.success());
        outputs.push(std::fs::read(&out).expect("written"));
    }
    assert!(outputs[0].len() > 64 * 48 * 12, "too small for a float EXR");
    assert_eq!(outputs[0], outputs[1]);
}

#[test]
fn png_is_written_and_seeds_change_the_noise() {
    let temp = scratch("png");
    let dir = temp.path();
    let render = |seed: &str, name: &str| {
        let out = dir.join(name);
        let status = penumbra()
            .args([
                "render",
                &scene("soft_shadow.pov"),
                "--quiet",
                "--width",
                "40",
            ])
            .args(["--height", "30", "--spp", "2", "--seed", seed, "--output"])
            .arg(&out)
            .status()
            .expect("runs");
        assert!(status.success());
        std::fs::read(out).expect("written")
    };
    let a = render("1", "a.png");
    let b = render("2", "b.png");
    assert_eq!(&a[1..4], b"PNG");
    assert_ne!(a, b, "different seeds gave the same noise");
}

#[test]
fn a_malformed_scene_points_at_the_error_and_writes_nothing() {
    let temp = scratch("broken");
    let dir = temp.path();
    let source = dir.join("broken.pov");
    std::fs::write(
        &source,
        "#version 3.7;\ncamera { location <0, 1, -3> look_at 0 }\nsphere { <0, 1, 0>, 1\n  pigment { color rgb <1, 0, 0> }\n  frobnicate 3\n}\n",
    )
    .expect("write scene");
    let out = dir.join("broken.png");
    let result = penumbra()
        .arg("render")
        .arg(&source)
        .arg("--output")
        .arg(&out)
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(!result.status.success(), "exit status was success");
    assert!(
        stderr.contains("broken.pov:5:3"),
        "no file:line:col in:\n{stderr}"
    );
    assert!(
        stderr.contains("frobnicate 3"),
        "source line missing:\n{stderr}"
    );
    assert!(
        stderr.contains("^^^^^^^^^^"),
        "no caret under the span:\n{stderr}"
    );
    assert!(!out.exists(), "an output file was written");
    let leftovers: Vec<_> = std::fs::read_dir(dir)
        .expect("list")
        .map(|e| e.expect("entry").file_name())
        .collect();
    assert_eq!(leftovers.len(), 1, "stray files: {leftovers:?}");
}

#[test]
fn a_bad_declare_is_refused() {
    let result = penumbra()
        .args(["render", &scene("soft_shadow.pov"), "--declare", "3x=1"])
        .output()
        .expect("runs");
    assert!(!result.status.success());
    assert!(String::from_utf8_lossy(&result.stderr).contains("not an identifier"));
}

/// A loop that would make 10^8 spheres, under a 4 GB address-space limit: the memory budget
/// (at most the address-space limit) stops it with an error naming the loop, well before the
/// machine's memory is gone, and nothing is written.
#[test]
fn a_hostile_loop_ends_with_the_memory_budget_error() {
    if Command::new("prlimit").arg("--version").output().is_err() {
        eprintln!("skipped: no prlimit");
        return;
    }
    let temp = scratch("hostile");
    let dir = temp.path();
    let source = dir.join("hostile.pov");
    std::fs::write(
        &source,
        "#declare I = 0;\n#while (I < 100000000)\n  sphere { <I, 0, 0>, 1 }\n  #declare I = I + 1;\n#end\n",
    )
    .expect("write scene");
    let out = dir.join("hostile.png");
    let start = std::time::Instant::now();
    let result = Command::new("prlimit")
        .arg("--as=4294967296")
        .arg(env!("CARGO_BIN_EXE_penumbra"))
        .arg("render")
        .arg(&source)
        .arg("--output")
        .arg(&out)
        .output()
        .expect("runs");
    let elapsed = start.elapsed().as_secs_f64();
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(!result.status.success(), "exit status was success");
    assert!(
        stderr.contains("the scene needs more than 4.0 GB (the memory budget): ")
            && stderr.contains("objects made by the `#while` loop at ")
            && stderr.contains("hostile.pov:2:1"),
        "not the budget error:\n{stderr}"
    );
    assert!(!out.exists(), "an output file was written");
    // Loose: it must end by itself, long before any test timeout.
    assert!(elapsed < 120.0, "took {elapsed:.0} s");
}

/// `#debug` text reaches stderr while rendering, as POV-Ray prints its debug stream, once per
/// frame of an animation (each frame parses the scene again), and under `--quiet` too;
/// POV-Ray's `-GD` silences it.
#[test]
fn render_prints_the_scenes_debug_text() {
    let temp = scratch("debug");
    let dir = temp.path();
    let source = dir.join("debug.pov");
    std::fs::write(
        &source,
        "#version 3.7;\n#debug concat(\"frame clock \", str(clock, 0, 2), \"\\n\")\n\
         camera { location -z look_at 0 }\n",
    )
    .expect("writes the scene");
    let run = |extra: &[&str]| {
        let out = penumbra()
            .arg("render")
            .arg(&source)
            .args(["--quiet", "--width", "8", "--height", "6", "--spp", "1"])
            .args(extra)
            .arg("--output")
            .arg(dir.join("debug.png"))
            .output()
            .expect("runs");
        assert!(out.status.success(), "{out:?}");
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    assert_eq!(run(&[]).matches("frame clock 0.00\n").count(), 1);
    // POV-Ray's switches: `-GD` turns the debug stream off, `+GD` (the default) on.
    let pov = |gd: &str| {
        let out = penumbra()
            .arg(&source)
            .args(["+W8", "+H6", "-V", gd])
            .arg(format!("+O{}", dir.join("debug_gd.png").display()))
            .output()
            .expect("runs");
        assert!(out.status.success(), "{out:?}");
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    let (off, on) = (pov("-GD"), pov("+GD"));
    assert!(!off.contains("frame clock"), "{off}");
    assert_eq!(on.matches("frame clock 0.00\n").count(), 1, "{on}");
    let frames = run(&["--frames", "1..3"]);
    for clock in ["0.00", "0.50", "1.00"] {
        assert!(
            frames.contains(&format!("frame clock {clock}\n")),
            "{frames}"
        );
    }
}
