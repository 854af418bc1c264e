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

fn povray(scene: &Path, dir: &Path, width: u32, height: u32) -> Result<Cost, String> {
    measure(
        Command::new("povray")
            .arg(format!("+I{}", scene.display()))
            .arg(format!("+O{}", dir.join("pov.png").display()))
            .args([format!("+W{width}"), format!("+H{height}")])
            .args(["-A", "-D", "-V", "-GA"]),
    )
}

fn penumbra(exe: &Path, scene: &Path, dir: &Path, width: u32, height: u32) -> Result<Cost, String> {
    measure(
        Command::new(exe)
            .arg("render")
            .arg(scene)
            .arg("-o")
            .arg(dir.join("penumbra.png"))
            .args([
                "--width",
                &width.to_string(),
                "--height",
                &height.to_string(),
            ])
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
    let ours = penumbra(exe, &scene, dir, size.0, size.1)?;
    let pov = povray(&scene, dir, size.0, size.1);
    let spheres = side * side;
    let per_object = ours.peak_bytes as f64 / spheres as f64;
    let theirs = match pov {
        Ok(p) => format!(
            "{:>9.2} {:>9.0} {:>8.2}x {:>8.2}x",
            p.seconds,
            megabytes(p.peak_bytes),
            p.seconds / ours.seconds,
            p.peak_bytes as f64 / ours.peak_bytes as f64
        ),
        Err(e) => format!("{e:>38}"),
    };
    Ok(format!(
        "{spheres:>9} {:>9.2} {:>9.0} {per_object:>10.0} {theirs}",
        ours.seconds,
        megabytes(ours.peak_bytes)
    ))
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
