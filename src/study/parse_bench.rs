//! `penumbra bench --parse`: how fast the scene language evaluates a loop, and what the
//! scene model holds per object, against POV-Ray's parse of the same file.
//!
//! The scene is N x N spheres over a plane made by two nested `#while` loops (the shape of
//! issue 16). penumbra's figure is the time to load the scene in this process, on one core
//! (the evaluator is single-threaded), and the resident memory the loaded scene holds, per
//! sphere (the largest of the runs: a later run may reuse memory an earlier one freed). POV-Ray's figure is the "Parse Time" it reports on stderr for a 16 x 12 render
//! without display (`-D +W16 +H12`), which times its parse alone. Each is run `repeats`
//! times, side by side, and the medians are printed.

use std::path::Path;
use std::process::Command;
use std::time::Instant;

use super::tempdir::TempDir;
use crate::lang::{LoadOptions, load_scene};

/// The N x N spheres scene.
pub fn grid_scene(side: usize) -> String {
    format!(
        "// {n} spheres over a plane, made with #while, for penumbra bench --parse.\n\
         #version 3.7;\n\
         camera {{ location <0, 20, -30> look_at <0, 0, 0> }}\n\
         light_source {{ <10, 50, -20> color rgb 1 }}\n\
         plane {{ y, 0 pigment {{ color rgb 0.8 }} }}\n\
         #declare N = {side};\n\
         #declare I = 0;\n\
         #while (I < N)\n\
           #declare J = 0;\n\
           #while (J < N)\n\
             sphere {{ <I - N/2, 0.5, J - N/2>, 0.4 pigment {{ color rgb <1, 0.5, 0.2> }} }}\n\
             #declare J = J + 1;\n\
           #end\n\
           #declare I = I + 1;\n\
         #end\n",
        n = side * side
    )
}

/// The resident set now, from /proc/self/status (bytes; 0 where unreadable).
fn resident_bytes() -> u64 {
    let Ok(text) = std::fs::read_to_string("/proc/self/status") else {
        return 0;
    };
    text.lines()
        .find(|l| l.starts_with("VmRSS:"))
        .and_then(|l| l.split_whitespace().nth(1)?.parse::<u64>().ok())
        .map_or(0, |kb| kb * 1024)
}

/// Seconds to load the scene, and the resident bytes the loaded scene adds.
fn penumbra_parse(path: &Path) -> Result<(f64, u64), String> {
    let before = resident_bytes();
    let start = Instant::now();
    let loaded = load_scene(path, &LoadOptions::default()).map_err(|d| d.to_string())?;
    let seconds = start.elapsed().as_secs_f64();
    let held = resident_bytes().saturating_sub(before);
    drop(loaded);
    Ok((seconds, held))
}

/// POV-Ray's own "Parse Time" for the scene (seconds).
fn povray_parse(path: &Path, dir: &Path) -> Result<f64, String> {
    let out = Command::new("povray")
        .arg(format!("+I{}", path.display()))
        .arg(format!("+O{}", dir.join("parse.png").display()))
        .args(["-D", "+W16", "+H12"])
        .output()
        .map_err(|e| format!("cannot run povray: {e}"))?;
    let stderr = String::from_utf8_lossy(&out.stderr);
    let line = stderr
        .lines()
        .find(|l| l.contains("Parse Time"))
        .ok_or("povray printed no Parse Time")?;
    // `  Parse Time:  0 hours  0 minutes  7 seconds (7.712 seconds)`
    line.rsplit_once('(')
        .and_then(|(_, r)| r.split_whitespace().next()?.parse().ok())
        .ok_or_else(|| format!("cannot read `{line}`"))
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// One row: sphere count, penumbra's median seconds, POV-Ray's (or its error), bytes per
/// sphere held by the loaded scene.
fn row(n: usize, repeats: usize, dir: &Path) -> Result<String, String> {
    let side = (n as f64).sqrt().round().max(1.0) as usize;
    let path = dir.join(format!("grid_{side}.pov"));
    std::fs::write(&path, grid_scene(side)).map_err(|e| e.to_string())?;
    let (mut ours, mut theirs, mut held) = (Vec::new(), Vec::new(), Vec::new());
    let mut pov_error = None;
    for _ in 0..repeats.max(1) {
        let (s, bytes) = penumbra_parse(&path)?;
        ours.push(s);
        held.push(bytes as f64);
        match povray_parse(&path, dir) {
            Ok(s) => theirs.push(s),
            Err(e) => pov_error = Some(e),
        }
    }
    let spheres = side * side;
    let ours = median(ours);
    // The largest: memory freed by an earlier run may be reused by a later one.
    let per_sphere = held.iter().copied().fold(0.0, f64::max) / spheres as f64;
    let pov = match (pov_error, theirs.is_empty()) {
        (Some(e), true) => format!("{e:>28}"),
        _ => {
            let pov = median(theirs);
            format!("{pov:>12.3} {:>15.2}x", pov / ours)
        }
    };
    Ok(format!(
        "{spheres:>9} {ours:>12.3} {pov} {per_sphere:>14.0}"
    ))
}

/// The section's lines.
pub fn run(counts: &[usize], repeats: usize, mut line: impl FnMut(String)) {
    line(format!(
        "parse: N x N spheres over a plane by #while; medians of {repeats}; penumbra: load in \
         this process (one core); POV-Ray: its Parse Time for -D +W16 +H12"
    ));
    line(format!(
        "{:>9} {:>12} {:>12} {:>16} {:>14}",
        "spheres", "penumbra (s)", "POV-Ray (s)", "POV-Ray/penumbra", "bytes/sphere"
    ));
    let dir = match TempDir::new("bench-parse") {
        Ok(d) => d,
        Err(e) => return line(format!("parse skipped: no temp dir ({e})")),
    };
    for &n in counts {
        match row(n, repeats, dir.path()) {
            Ok(text) => line(text),
            Err(e) => line(format!("{n:>9} spheres: skipped: {e}")),
        }
    }
}
