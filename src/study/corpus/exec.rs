//! Child processes with a time limit: each parse, render and reference of the sweep runs as
//! its own `penumbra` process under coreutils `timeout`, so a panic, an abort or a slow
//! scene becomes a row of the table instead of stopping the sweep. `timeout` signals its
//! whole process group, so POV-Ray started by `penumbra reference` is stopped too.

use std::ffi::OsString;
use std::process::{Command, Stdio};
use std::time::Instant;

/// How a child process ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Ended {
    Success,
    /// Exit status or signal, as text.
    Failed(String),
    TimedOut,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Finished {
    pub ended: Ended,
    pub stderr: String,
    pub seconds: f64,
}

impl Finished {
    /// A panic message, or else the first line starting with `error`, or else the last
    /// non-empty line of stderr.
    pub fn message(&self) -> String {
        let lines: Vec<&str> = self
            .stderr
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .collect();
        let panic = lines.iter().position(|l| l.contains("panicked"));
        if let Some(i) = panic {
            return lines[i..(i + 2).min(lines.len())].join(" ");
        }
        lines
            .iter()
            .find(|l| l.to_ascii_lowercase().starts_with("error"))
            .or(lines.last())
            .map_or_else(String::new, |l| l.to_string())
    }

    pub fn panicked(&self) -> bool {
        self.stderr.contains("panicked")
    }
}

/// Runs `program args` for at most `seconds` (then SIGTERM, and SIGKILL 10 s later), with
/// stdin closed and stdout discarded.
pub fn run_limited(program: &OsString, args: &[OsString], seconds: u64) -> Finished {
    let start = Instant::now();
    let output = Command::new("timeout")
        .arg("-k")
        .arg("10")
        .arg(seconds.max(1).to_string())
        .arg(program)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .output();
    let seconds = start.elapsed().as_secs_f64();
    match output {
        Err(e) => Finished {
            ended: Ended::Failed(format!("cannot start `timeout`: {e}")),
            stderr: String::new(),
            seconds,
        },
        Ok(out) => {
            let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
            let ended = match out.status.code() {
                Some(0) => Ended::Success,
                Some(124 | 137) => Ended::TimedOut,
                _ => Ended::Failed(out.status.to_string()),
            };
            Finished {
                ended,
                stderr,
                seconds,
            }
        }
    }
}

/// POV-Ray's version line (`POV-Ray 3.7.0.10.unofficial`), part of every reference's cache
/// key; "unknown" if it cannot be run.
pub fn povray_version() -> String {
    Command::new("povray")
        .arg("--version")
        .stdin(Stdio::null())
        .output()
        .ok()
        .and_then(|out| {
            let text = format!(
                "{}\n{}",
                String::from_utf8_lossy(&out.stdout),
                String::from_utf8_lossy(&out.stderr)
            );
            text.lines()
                .find(|l| l.starts_with("POV-Ray "))
                .map(|l| l.trim().to_string())
        })
        .unwrap_or_else(|| "unknown".to_string())
}
