//! Renders split over machines and time: shards merge into exactly the single render,
//! foreign or incomplete shards are refused with a reason, output bytes do not depend on
//! the thread count, and an interrupted render resumes to the uninterrupted bytes.

use penumbra::study::TempDir;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn penumbra() -> Command {
    Command::new(env!("CARGO_BIN_EXE_penumbra"))
}

fn scene(name: &str) -> String {
    format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// `render` of soft_shadow.pov at 96x72, 16 spp, seed 7, with more arguments.
fn render(extra: &[&str], out: &Path) -> Output {
    penumbra()
        .args(["render", &scene("soft_shadow.pov"), "-q", "--width", "96"])
        .args(["--height", "72", "--spp", "16", "--seed", "7"])
        .args(extra)
        .arg("-o")
        .arg(out)
        .output()
        .expect("runs")
}

fn ok(output: Output) -> Output {
    assert!(
        output.status.success(),
        "failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

/// Shard k of n over 16 samples, as the Slurm script computes it.
fn shard_range(k: u32, n: u32) -> String {
    format!("{}..{}", k * 16 / n, (k + 1) * 16 / n)
}

fn shards(dir: &Path, n: u32, threads: &str, sampling: &[&str]) -> Vec<PathBuf> {
    (0..n)
        .map(|k| {
            let path = dir.join(format!("n{n}-{k}.pshard"));
            let range = shard_range(k, n);
            let mut args = vec!["--sample-range", &range, "--threads", threads];
            args.extend_from_slice(sampling);
            ok(render(&args, &path));
            path
        })
        .collect()
}

fn merge(shards: &[PathBuf], out: &Path) -> Output {
    penumbra()
        .arg("merge")
        .args(shards)
        .arg("-o")
        .arg(out)
        .output()
        .expect("runs")
}

#[test]
fn one_three_and_seven_shards_merge_into_the_single_render_byte_for_byte() {
    let temp = TempDir::new("farm-merge").expect("temp dir");
    let dir = temp.path();
    // Adaptive sampling (the default at 16 spp) into PNG, uniform into EXR.
    for (ext, sampling) in [("png", &[][..]), ("exr", &["--uniform"][..])] {
        let single = dir.join(format!("single.{ext}"));
        ok(render(sampling, &single));
        let want = std::fs::read(&single).expect("written");
        for n in [1, 3, 7] {
            let mut parts = shards(dir, n, if n == 3 { "1" } else { "2" }, sampling);
            // Any order.
            parts.reverse();
            let out = dir.join(format!("merged{n}.{ext}"));
            ok(merge(&parts, &out));
            assert_eq!(
                std::fs::read(&out).expect("merged"),
                want,
                "{n} shards, {ext}"
            );
        }
    }
}

/// `render` samples adaptively from 2 samples per pixel on and uniformly at 1, unless told.
#[test]
fn the_default_sampling_is_adaptive_from_two_samples_per_pixel() {
    let temp = TempDir::new("farm-default").expect("temp dir");
    let dir = temp.path();
    // The image, and whether the render's summary says it sampled adaptively.
    let render = |spp: &str, sampling: &[&str]| {
        let out = dir.join("x.exr");
        let run = ok(penumbra()
            .args(["render", &scene("soft_shadow.pov"), "--width", "48"])
            .args(["--height", "36", "--spp", spp, "--seed", "7"])
            .args(sampling)
            .arg("-o")
            .arg(&out)
            .output()
            .expect("runs"));
        let adaptive = String::from_utf8_lossy(&run.stderr).contains(" spp adaptive");
        (std::fs::read(&out).expect("written"), adaptive)
    };
    let default = render("16", &[]);
    assert!(default.1);
    assert_eq!(default, render("16", &["--adaptive"]));
    assert_ne!(default.0, render("16", &["--uniform"]).0);
    // At 1 spp the adaptive pilot's kept samples can be the uniform render's own (their
    // positions are point 0 of the same sequences), so the summary tells them apart.
    let one = render("1", &[]);
    assert!(!one.1);
    assert_eq!(one, render("1", &["--uniform"]));
    assert!(render("1", &["--adaptive"]).1);
}

#[test]
fn shards_that_do_not_belong_together_are_refused_with_the_reason() {
    let temp = TempDir::new("farm-refuse").expect("temp dir");
    let dir = temp.path();
    let parts = shards(dir, 3, "2", &[]);
    let out = dir.join("out.png");
    let refused = |shards: &[PathBuf], reason: &str| {
        let o = merge(shards, &out);
        let err = String::from_utf8_lossy(&o.stderr).to_string();
        assert!(!o.status.success(), "merged: {shards:?}");
        assert!(err.contains(reason), "`{reason}` not in: {err}");
        assert!(!out.exists(), "an image was written");
    };
    refused(
        &[parts[0].clone(), parts[2].clone()],
        "samples 5..10 are missing",
    );
    refused(&parts[..2], "samples 10..16 are missing");
    let mut twice = parts.clone();
    twice.push(parts[1].clone());
    refused(&twice, "overlaps");
    // Shard 1 of another seed, and of another scene.
    let middle = |name: &str, seed: &str, out: &Path| {
        ok(penumbra()
            .args([
                "render",
                &scene(name),
                "-q",
                "--width",
                "96",
                "--height",
                "72",
            ])
            .args([
                "--spp",
                "16",
                "--seed",
                seed,
                "--sample-range",
                "5..10",
                "-o",
            ])
            .arg(out)
            .output()
            .expect("runs"))
    };
    let seed = dir.join("seed.pshard");
    middle("soft_shadow.pov", "8", &seed);
    refused(
        &[parts[0].clone(), seed, parts[2].clone()],
        "seed 7 against 8",
    );
    let other = dir.join("other.pshard");
    middle("reflection.pov", "7", &other);
    refused(
        &[parts[0].clone(), other, parts[2].clone()],
        "different scenes",
    );
    // A damaged file: one byte changed.
    let damaged = dir.join("damaged.pshard");
    let mut bytes = std::fs::read(&parts[1]).expect("shard");
    let at = bytes.len() / 2;
    bytes[at] ^= 1;
    std::fs::write(&damaged, bytes).expect("written");
    refused(&[parts[0].clone(), damaged, parts[2].clone()], "damaged");
}

#[test]
fn a_shard_needs_a_shard_output_and_an_image_no_range() {
    let temp = TempDir::new("farm-names").expect("temp dir");
    let dir = temp.path();
    let o = render(&["--sample-range", "0..4"], &dir.join("x.png"));
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains(".pshard"));
    let o = render(&[], &dir.join("x.pshard"));
    assert!(!o.status.success());
    assert!(
        std::fs::read_dir(dir).expect("dir").next().is_none(),
        "wrote something"
    );
}

#[test]
fn exr_and_shard_bytes_do_not_depend_on_threads_at_any_size() {
    let temp = TempDir::new("farm-threads").expect("temp dir");
    let dir = temp.path();
    for (w, h) in [(96, 72), (333, 127), (17, 5)] {
        for ext in ["exr", "pshard"] {
            let files: Vec<Vec<u8>> = ["1", "2"]
                .iter()
                .map(|t| {
                    let out = dir.join(format!("t{t}.{ext}"));
                    let mut args = vec!["--threads", t, "--spp", "2"];
                    if ext == "pshard" {
                        args.extend(["--sample-range", "0..2"]);
                    }
                    ok(penumbra()
                        .args(["render", &scene("soft_shadow.pov"), "-q"])
                        .args(["--width", &w.to_string(), "--height", &h.to_string()])
                        .args(&args)
                        .arg("-o")
                        .arg(&out)
                        .output()
                        .expect("runs"));
                    std::fs::read(out).expect("written")
                })
                .collect();
            assert_eq!(files[0], files[1], "{w}x{h} {ext}");
        }
    }
}

/// A render long enough to interrupt: 320x240 at 64 spp on one thread (about 3 s here).
fn long_render(out: &Path, extra: &[&str]) -> Command {
    let mut c = penumbra();
    c.args(["render", &scene("soft_shadow.pov"), "-q", "--width", "320"])
        .args([
            "--height",
            "240",
            "--spp",
            "64",
            "--seed",
            "3",
            "--threads",
            "1",
        ])
        .args(extra)
        .arg("-o")
        .arg(out);
    c
}

/// A delay in [lo, hi) seconds that differs from run to run (the moment is meant to be
/// arbitrary; whatever it is, the bytes must agree).
fn arbitrary_delay(lo: f64, hi: f64) -> Duration {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    Duration::from_secs_f64(lo + (hi - lo) * f64::from(nanos % 1000) / 1000.0)
}

/// Starts the render, signals it after `delay`, and returns how long it took to exit.
fn interrupt(mut command: Command, delay: Duration, signal: &str) -> (Output, Duration) {
    let child = command
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("starts");
    std::thread::sleep(delay);
    let sent = Instant::now();
    let status = Command::new("kill")
        .args([signal, &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(status.success());
    let output = child.wait_with_output().expect("ends");
    (output, sent.elapsed())
}

#[test]
fn an_interrupted_render_resumes_to_the_same_bytes() {
    let temp = TempDir::new("farm-resume").expect("temp dir");
    let dir = temp.path();
    // Adaptive (the default at 64 spp), then uniform.
    for (signal, name, sampling) in [
        ("-INT", "int.png", &[][..]),
        ("-TERM", "term.png", &["--uniform"][..]),
    ] {
        let whole = dir.join(format!("whole-{name}"));
        let started = Instant::now();
        ok(long_render(&whole, sampling).output().expect("runs"));
        let full_time = started.elapsed().as_secs_f64();
        let out = dir.join(name);
        let delay = arbitrary_delay(0.1, (0.6 * full_time).max(0.2));
        let (o, stop) = interrupt(long_render(&out, sampling), delay, signal);
        let err = String::from_utf8_lossy(&o.stderr).to_string();
        assert_eq!(
            o.status.code(),
            Some(130),
            "{signal} after {delay:?}: {err}"
        );
        assert!(err.contains("--resume"), "{err}");
        assert!(stop < Duration::from_secs(1), "took {stop:?} to stop");
        assert!(!out.exists(), "a half-rendered image was written");
        let checkpoint = dir.join(format!("{name}.checkpoint"));
        assert!(checkpoint.exists());
        let resume = [sampling, &["--resume"]].concat();
        ok(long_render(&out, &resume).output().expect("runs"));
        assert_eq!(
            std::fs::read(&out).expect("resumed"),
            std::fs::read(&whole).expect("whole"),
            "{signal} after {delay:?}, {sampling:?}"
        );
        assert!(!checkpoint.exists(), "the checkpoint was left behind");
    }
}

#[test]
fn a_checkpoint_of_another_render_is_refused_and_is_no_shard() {
    let temp = TempDir::new("farm-foreign").expect("temp dir");
    let dir = temp.path();
    let out = dir.join("x.png");
    let (o, _) = interrupt(long_render(&out, &[]), Duration::from_millis(300), "-INT");
    assert_eq!(o.status.code(), Some(130));
    let checkpoint = dir.join("x.png.checkpoint");
    // Another seed cannot continue it.
    let o = penumbra()
        .args(["render", &scene("soft_shadow.pov"), "-q", "--width", "320"])
        .args([
            "--height", "240", "--spp", "64", "--seed", "4", "--resume", "-o",
        ])
        .arg(&out)
        .output()
        .expect("runs");
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("another render"));
    // Nor can it be merged as if it were complete.
    let o = merge(&[checkpoint], &dir.join("m.png"));
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("checkpoint"));
}

#[test]
fn an_interrupted_shard_resumes_to_the_same_shard() {
    let temp = TempDir::new("farm-shard-resume").expect("temp dir");
    let dir = temp.path();
    let whole = dir.join("whole.pshard");
    ok(long_render(&whole, &["--sample-range", "10..50"])
        .output()
        .expect("runs"));
    let out = dir.join("part.pshard");
    let (o, _) = interrupt(
        long_render(&out, &["--sample-range", "10..50"]),
        arbitrary_delay(0.1, 1.0),
        "-INT",
    );
    assert_eq!(o.status.code(), Some(130));
    ok(long_render(&out, &["--sample-range", "10..50", "--resume"])
        .output()
        .expect("runs"));
    assert_eq!(std::fs::read(&out).unwrap(), std::fs::read(&whole).unwrap());
}

#[test]
fn a_preview_is_written_and_the_image_is_unchanged() {
    let temp = TempDir::new("farm-preview").expect("temp dir");
    let dir = temp.path();
    let plain = dir.join("plain.png");
    ok(render(&[], &plain));
    let out = dir.join("with.png");
    let preview = dir.join("preview.png");
    ok(render(
        &[
            "--preview",
            preview.to_str().expect("utf-8"),
            "--preview-every",
            "0",
        ],
        &out,
    ));
    assert_eq!(std::fs::read(&out).unwrap(), std::fs::read(&plain).unwrap());
    let image = penumbra::output::read_image(&preview).expect("a PNG preview");
    assert_eq!((image.width, image.height), (96, 72));
}

#[test]
fn povray_switches_interrupt_and_continue_with_plus_c() {
    let temp = TempDir::new("farm-plus-c").expect("temp dir");
    let dir = temp.path();
    let whole = dir.join("whole.png");
    ok(long_render(&whole, &[]).output().expect("runs"));
    let out = dir.join("pov.png");
    let povray_style = |extra: &[&str]| {
        let mut c = penumbra();
        c.args(["render", &scene("soft_shadow.pov"), "+W320", "+H240", "-V"])
            .args(["--spp", "64", "--seed", "3", "+WT1"])
            .arg(format!("+O{}", out.display()))
            .args(extra);
        c
    };
    let (o, _) = interrupt(povray_style(&[]), arbitrary_delay(0.1, 1.0), "-INT");
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert_eq!(o.status.code(), Some(130), "{err}");
    assert!(err.trim_end().ends_with("+C"), "{err}");
    ok(povray_style(&["+C"]).output().expect("runs"));
    assert_eq!(std::fs::read(&out).unwrap(), std::fs::read(&whole).unwrap());
}

/// `--spp 1.5` is an adaptive render's average: more samples than one per pixel and fewer
/// than two (each pixel's share is rounded, so not exactly 1.5), an image of its own,
/// shards that merge into it byte for byte, and a clear refusal where sampling is uniform.
#[test]
fn a_fractional_spp_is_an_adaptive_average() {
    let temp = TempDir::new("farm-fractional").expect("temp dir");
    let dir = temp.path();
    let render = |spp: &str, extra: &[&str], out: &Path| {
        penumbra()
            .args(["render", &scene("checker.pov"), "--width", "64"])
            .args(["--height", "48", "--spp", spp, "--seed", "3"])
            .args(extra)
            .arg("-o")
            .arg(out)
            .output()
            .expect("runs")
    };
    // The image and the summary's sample count.
    let image = |spp: &str| {
        let out = dir.join(format!("spp{spp}.exr"));
        let run = ok(render(spp, &[], &out));
        let summary = String::from_utf8_lossy(&run.stderr).to_string();
        let samples: u64 = summary
            .split(", ")
            .find_map(|part| part.strip_suffix(" samples")?.parse().ok())
            .unwrap_or_else(|| panic!("no sample count in: {summary}"));
        (std::fs::read(&out).expect("written"), samples, summary)
    };
    let pixels = 64 * 48;
    let (one, half, two) = (image("1"), image("1.5"), image("2"));
    assert!(half.2.contains("1.5 spp adaptive"), "{}", half.2);
    assert_eq!(one.1, pixels);
    assert!(
        half.1 > pixels && half.1 < two.1,
        "{} against {}",
        half.1,
        two.1
    );
    assert!(half.0 != one.0 && half.0 != two.0);
    // Shards of the average merge into its render.
    let parts: Vec<PathBuf> = ["0..1", "1..2"]
        .iter()
        .map(|range| {
            let path = dir.join(format!("half-{}.pshard", &range[..1]));
            ok(render("1.5", &["--sample-range", range], &path));
            path
        })
        .collect();
    let merged = dir.join("merged.exr");
    ok(merge(&parts, &merged));
    assert_eq!(std::fs::read(&merged).expect("merged"), half.0);
    // Uniform sampling takes whole samples.
    let refused = dir.join("uniform.exr");
    let run = render("1.5", &["--uniform"], &refused);
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success() && err.contains("average"), "{err}");
    assert!(!refused.exists());
}
