//! `penumbra bench --pipeline`: the whole pipeline (read, evaluate, prepare, render, write)
//! on the N x N spheres scene of `--parse`, as a user runs it, against POV-Ray on the same
//! file in the same run: wall time and peak memory of each process.
//!
//! Both are child processes, so start-up counts for both (it is reported apart for 16 x 12
//! images of the smallest scene), and peak memory is the kernel's high-water mark of each
//! child's resident set (`wait4`'s `ru_maxrss`), not an estimate. penumbra renders 1 sample
//! per pixel, POV-Ray renders without anti-aliasing (`-A`): one camera ray per pixel each.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

use super::parse_bench::grid_scene;
use super::tempdir::TempDir;

/// What one child process cost.
#[derive(Clone, Copy, Debug)]
struct Cost {
    seconds: f64,
    peak_bytes: u64,
}

/// Runs the command to its end and reads its peak resident set from the kernel.
fn measure(cmd: &mut Command) -> Result<Cost, String> {
    let name = cmd.get_program().to_string_lossy().into_owned();
    let start = Instant::now();
    let child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot run {name}: {e}"))?;
    let pid = child.id() as libc::pid_t;
    // Read stderr first so a chatty child cannot block on a full pipe.
    let mut stderr = child.stderr.expect("piped");
    let mut message = String::new();
    let _ = std::io::Read::read_to_string(&mut stderr, &mut message);
    let mut status = 0;
    // SAFETY: an all-zero rusage is a valid value to be overwritten by wait4.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: pid is this process's child, not yet reaped (Child::wait was not called),
    // and both pointers are to live locals.
    let reaped = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    let seconds = start.elapsed().as_secs_f64();
    if reaped != pid {
        return Err(format!("cannot wait for {name}"));
    }
    if !libc::WIFEXITED(status) || libc::WEXITSTATUS(status) != 0 {
        let last = message.lines().last().unwrap_or("").to_string();
        return Err(format!("{name} failed: {last}"));
    }
    Ok(Cost {
        seconds,
        peak_bytes: usage.ru_maxrss.max(0) as u64 * 1024,
    })
}

/// Identifiers a run defines before the scene is read (`Declare=` / `--declare`).
type Declares<'a> = &'a [(&'a str, usize)];

fn povray(scene: &Path, dir: &Path, size: (u32, u32), declares: Declares) -> Result<Cost, String> {
    measure(
        Command::new("povray")
            .arg(format!("+I{}", scene.display()))
            .arg(format!("+O{}", dir.join("pov.png").display()))
            .args([format!("+W{}", size.0), format!("+H{}", size.1)])
            .args(declares.iter().map(|(k, v)| format!("Declare={k}={v}")))
            .args(["-A", "-D", "-V", "-GA"]),
    )
}

fn penumbra(
    exe: &Path,
    scene: &Path,
    dir: &Path,
    size: (u32, u32),
    declares: Declares,
) -> Result<Cost, String> {
    measure(
        Command::new(exe)
            .arg("render")
            .arg(scene)
            .arg("-o")
            .arg(dir.join("penumbra.png"))
            .args(["--width", &size.0.to_string()])
            .args(["--height", &size.1.to_string()])
            .args(declares.iter().map(|(k, v)| format!("--declare={k}={v}")))
            .args(["--spp", "1", "-q"]),
    )
}

fn megabytes(bytes: u64) -> f64 {
    bytes as f64 / (1024.0 * 1024.0)
}

/// One row: both renderers on the scene of about `n` spheres.
fn row(n: usize, exe: &Path, dir: &Path, size: (u32, u32)) -> Result<String, String> {
    let side = (n as f64).sqrt().round().max(1.0) as usize;
    let scene = dir.join(format!("grid_{side}.pov"));
    std::fs::write(&scene, grid_scene(side)).map_err(|e| e.to_string())?;
    let ours = penumbra(exe, &scene, dir, size, &[])?;
    let pov = povray(&scene, dir, size, &[]);
    let spheres = side * side;
    let per_object = ours.peak_bytes as f64 / spheres as f64;
    Ok(format!(
        "{spheres:>9} {:>9.2} {:>9.0} {per_object:>10.0} {}",
        ours.seconds,
        megabytes(ours.peak_bytes),
        beside(&ours, pov)
    ))
}

/// POV-Ray's columns: its time and memory, and both over penumbra's.
fn beside(ours: &Cost, pov: Result<Cost, String>) -> String {
    match pov {
        Ok(p) => format!(
            "{:>9.2} {:>9.0} {:>8.2}x {:>8.2}x",
            p.seconds,
            megabytes(p.peak_bytes),
            p.seconds / ours.seconds,
            p.peak_bytes as f64 / ours.peak_bytes as f64
        ),
        Err(e) => format!("{e:>38}"),
    }
}

/// scenes/forest.pov: one declared tree of `parts` objects placed `trees` x `trees` times,
/// which penumbra shares and POV-Ray copies.
const FOREST: &str = include_str!("../../scenes/forest.pov");

/// `penumbra bench --forest`: the forest at each size, both renderers, time and peak memory.
pub fn forest(
    sizes: &[(usize, usize)],
    exe: &Path,
    size: (u32, u32),
    mut line: impl FnMut(String),
) {
    line(format!(
        "forest: scenes/forest.pov, Trees x Trees placements of a tree of Parts objects, {}x{}, \
         whole process each; penumbra 1 spp on all cores, POV-Ray -A",
        size.0, size.1
    ));
    let dir = match TempDir::new("bench-forest") {
        Ok(d) => d,
        Err(e) => return line(format!("forest skipped: no temp dir ({e})")),
    };
    let scene = dir.path().join("forest.pov");
    if let Err(e) = std::fs::write(&scene, FOREST) {
        return line(format!("forest skipped: {e}"));
    }
    line(format!(
        "{:>7} {:>6} {:>11} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "trees",
        "parts",
        "objects",
        "ours (s)",
        "ours (MB)",
        "POV (s)",
        "POV (MB)",
        "time",
        "memory"
    ));
    for &(trees, parts) in sizes {
        let declares = [("Trees", trees), ("Parts", parts)];
        let objects = trees * trees * parts;
        match penumbra(exe, &scene, dir.path(), size, &declares) {
            Ok(ours) => line(format!(
                "{:>7} {parts:>6} {objects:>11} {:>9.2} {:>9.0} {}",
                trees * trees,
                ours.seconds,
                megabytes(ours.peak_bytes),
                beside(&ours, povray(&scene, dir.path(), size, &declares))
            )),
            Err(e) => line(format!("{trees}x{trees} trees of {parts}: skipped: {e}")),
        }
    }
    line("time and memory columns: POV-Ray's over penumbra's (above 1: penumbra ahead)".into());
}

/// The section's lines.
pub fn run(counts: &[usize], exe: &Path, size: (u32, u32), mut line: impl FnMut(String)) {
    line(format!(
        "pipeline: N x N spheres over a plane by #while, {}x{}, whole process each (parse, \
         evaluate, prepare, render, write); penumbra 1 spp on all cores, POV-Ray -A",
        size.0, size.1
    ));
    let dir = match TempDir::new("bench-pipeline") {
        Ok(d) => d,
        Err(e) => return line(format!("pipeline skipped: no temp dir ({e})")),
    };
    match row(1, exe, dir.path(), (16, 12)) {
        Ok(text) => line(format!("start-up (1 sphere, 16x12):\n{text}")),
        Err(e) => line(format!("start-up skipped: {e}")),
    }
    line(format!(
        "{:>9} {:>9} {:>9} {:>10} {:>9} {:>9} {:>9} {:>9}",
        "spheres", "ours (s)", "ours (MB)", "B/sphere", "POV (s)", "POV (MB)", "time", "memory"
    ));
    for &n in counts {
        match row(n, exe, dir.path(), size) {
            Ok(text) => line(text),
            Err(e) => line(format!("{n:>9} spheres: skipped: {e}")),
        }
    }
    line("time and memory columns: POV-Ray's over penumbra's (above 1: penumbra ahead)".into());
}
