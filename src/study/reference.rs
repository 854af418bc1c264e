//! Converged POV-Ray references, rendered by the installed `povray`.
//!
//! POV-Ray's anti-aliasing is adaptive, so its output is not a fixed box filter. A reference
//! is instead rendered k times larger without anti-aliasing and averaged over k x k blocks:
//! an exact box filter with k^2 regular samples per pixel. The same scene is also rendered
//! at k/2, because r_k - r_k/2 bounds the reference's own quadrature error, which the
//! statistics subtract (see `metrics`).
//!
//! POV-Ray 3.7.0.10's `+FE` output was checked to be linear half float (16-bit): a constant
//! `rgb 0.123456` reads back as 0.12347 (the nearest half), not as its sRGB encoding, and
//! `File_Gamma` does not change EXR output. No gamma option is needed.

use super::StudyError;
use super::media_quadrature;
use super::tempdir::TempDir;
use crate::output::{Image, read_exr, write_exr};
use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// Largest supersampling factor accepted: 64 already means 4096 samples per pixel.
pub const MAX_SUPERSAMPLE: u32 = 64;
/// How many of POV-Ray's last output lines an error carries.
const ERROR_LINES: usize = 25;

#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceRequest {
    pub scene: PathBuf,
    /// Size of the final (averaged) reference image.
    pub width: u32,
    pub height: u32,
    /// k: the render is k times larger in each direction. Even and at least 2, so that the
    /// k/2 companion exists.
    pub supersample: u32,
    /// Passed as `Declare=Name=Value`, for scenes parameterised by the study.
    pub declares: Vec<(String, f64)>,
    /// Extra include folders; the scene's own folder is always searched.
    pub include_paths: Vec<PathBuf>,
    /// Passed as `+K` (the `clock` of a still): one frame of an animation.
    pub clock: Option<f64>,
    /// Options given to POV-Ray before the runner's own (which therefore win over them): an
    /// INI file the scene needs, `+SF1 +EF1` to render one frame of its animation.
    pub extra_args: Vec<String>,
    /// How POV-Ray integrates the scene's media (`media_quadrature`).
    pub media: MediaQuadrature,
}

/// POV-Ray's media quadrature in a reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MediaQuadrature {
    /// The scene's own `method`, `intervals` and `samples`.
    #[default]
    AsWritten,
    /// Every media block at `method 2 intervals 10 samples 10`: the integral penumbra
    /// estimates, where POV-Ray's default overshoots it.
    Converged,
}

impl ReferenceRequest {
    pub fn new(scene: impl Into<PathBuf>, width: u32, height: u32, supersample: u32) -> Self {
        ReferenceRequest {
            scene: scene.into(),
            width,
            height,
            supersample,
            declares: Vec::new(),
            include_paths: Vec::new(),
            clock: None,
            extra_args: Vec::new(),
            media: MediaQuadrature::AsWritten,
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct Reference {
    /// The k-supersampled reference r.
    pub full: Image,
    /// The k/2-supersampled companion r2.
    pub half: Image,
    /// k.
    pub supersample: u32,
    /// Wall time of POV-Ray's k render, process start to exit (parsing included), for
    /// speed charts.
    pub povray_seconds: f64,
}

/// Renders `req` at k and at k/2 and box-filters both down to width x height.
pub fn render_reference(req: &ReferenceRequest) -> Result<Reference, StudyError> {
    validate(req)?;
    let runner = PovrayRunner::new(req)?;
    let full = runner.render(req.supersample, &["-A"], None)?;
    // k = 1 (a camera whose rays do not fill the pixel, like a mesh camera's): one ray per
    // pixel is the converged image, and it stands in for its own k/2 render.
    let half = if req.supersample == 1 {
        full.image.clone()
    } else {
        runner.render(req.supersample / 2, &["-A"], None)?.image
    };
    let povray_seconds = full.seconds;
    let full = full.image;
    Ok(Reference {
        full,
        half,
        supersample: req.supersample,
        povray_seconds,
    })
}

/// One POV-Ray render and its times.
#[derive(Debug, Clone, PartialEq)]
pub struct PovrayRun {
    pub image: Image,
    /// Process wall time, start to exit.
    pub seconds: f64,
    /// POV-Ray's own parse, bounding, photon, radiosity and trace times, summed. Its
    /// process spends a fixed ~0.6 s besides (start-up and shut-down), which at study sizes
    /// would hide the rendering itself. `None` if the statistics could not be read.
    pub reported_seconds: Option<f64>,
}

/// Renders `req`'s scene once at width x height (the supersample factor is ignored) with
/// POV-Ray's own anti-aliasing options, e.g. `["+A0.3", "+AM2", "+R3"]`: one point of a
/// speed-against-accuracy chart.
pub fn render_povray(
    req: &ReferenceRequest,
    antialias: &[&str],
    threads: Option<usize>,
) -> Result<PovrayRun, StudyError> {
    validate(&ReferenceRequest {
        supersample: 2,
        ..req.clone()
    })?;
    PovrayRunner::new(req)?.render(1, antialias, threads)
}

/// The installed povray, the scene and a private working directory, shared by the renders
/// of one request.
struct PovrayRunner<'a> {
    povray: PathBuf,
    scene: PathBuf,
    include_paths: Vec<PathBuf>,
    req: &'a ReferenceRequest,
    dir: TempDir,
}

impl<'a> PovrayRunner<'a> {
    fn new(req: &'a ReferenceRequest) -> Result<Self, StudyError> {
        let povray = find_povray()?;
        let scene = std::fs::canonicalize(&req.scene).map_err(|source| StudyError::Io {
            path: req.scene.clone(),
            source,
        })?;
        if !scene.is_file() {
            return Err(StudyError::InvalidRequest(format!(
                "{} is not a file",
                scene.display()
            )));
        }
        let mut include_paths = Vec::new();
        if let Some(folder) = scene.parent() {
            include_paths.push(folder.to_path_buf());
        }
        for path in &req.include_paths {
            include_paths.push(std::path::absolute(path).map_err(|source| StudyError::Io {
                path: path.clone(),
                source,
            })?);
        }
        let dir = TempDir::new("reference").map_err(|source| StudyError::Io {
            path: std::env::temp_dir(),
            source,
        })?;
        let scene = match req.media {
            MediaQuadrature::AsWritten => scene,
            MediaQuadrature::Converged => converged_copy(&scene, dir.path())?,
        };
        Ok(PovrayRunner {
            povray,
            scene,
            include_paths,
            req,
            dir,
        })
    }
}

/// The scene rewritten by `media_quadrature::converged` into `dir`, under its own name (its
/// folder stays first on the include path, so its includes and data files are still found).
fn converged_copy(scene: &Path, dir: &Path) -> Result<PathBuf, StudyError> {
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| StudyError::Io { path, source }
    };
    let text = std::fs::read(scene).map_err(io(scene))?;
    let copy = dir.join(scene.file_name().unwrap_or(OsStr::new("scene.pov")));
    std::fs::write(&copy, media_quadrature::converged(&text)).map_err(io(&copy))?;
    Ok(copy)
}

/// Stores the k render as the main RGB image, the k/2 render as layer `half`, and k and
/// the wall time as string attributes.
pub fn write_reference(path: &Path, reference: &Reference) -> Result<(), StudyError> {
    let seconds = format!("{}", reference.povray_seconds);
    let supersample = reference.supersample.to_string();
    write_exr(
        path,
        &reference.full,
        &[("half", &reference.half)],
        &[
            ("povray_seconds", seconds.as_str()),
            ("supersample", supersample.as_str()),
        ],
    )?;
    Ok(())
}

pub fn read_reference(path: &Path) -> Result<Reference, StudyError> {
    let file = read_exr(path)?;
    let bad = |message: &str| StudyError::BadReferenceFile {
        path: path.to_path_buf(),
        message: message.to_string(),
    };
    let half = file
        .layer("half")
        .cloned()
        .ok_or_else(|| bad("no `half` layer (the k/2 render)"))?;
    let povray_seconds = file
        .attribute("povray_seconds")
        .and_then(|s| s.parse::<f64>().ok())
        .ok_or_else(|| bad("no numeric `povray_seconds` attribute"))?;
    let supersample = file
        .attribute("supersample")
        .and_then(|s| s.parse::<u32>().ok())
        .ok_or_else(|| bad("no integer `supersample` attribute"))?;
    Ok(Reference {
        full: file.image,
        half,
        supersample,
        povray_seconds,
    })
}

/// The `povray` executable on PATH.
pub fn find_povray() -> Result<PathBuf, StudyError> {
    let path = std::env::var_os("PATH").unwrap_or_default();
    find_in_path("povray", &path).ok_or(StudyError::PovrayNotFound)
}

fn find_in_path(name: &str, path_var: &OsStr) -> Option<PathBuf> {
    std::env::split_paths(path_var)
        .filter(|dir| !dir.as_os_str().is_empty())
        .map(|dir| dir.join(name))
        .find(|candidate| is_executable(candidate))
}

#[cfg(unix)]
fn is_executable(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    std::fs::metadata(path)
        .map(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
        .unwrap_or(false)
}

#[cfg(not(unix))]
fn is_executable(path: &Path) -> bool {
    path.is_file()
}

fn validate(req: &ReferenceRequest) -> Result<(), StudyError> {
    let invalid = |message: String| Err(StudyError::InvalidRequest(message));
    if req.width == 0 || req.height == 0 {
        return invalid(format!("size {}x{} is empty", req.width, req.height));
    }
    let k = req.supersample;
    if k != 1 && (k < 2 || !k.is_multiple_of(2) || k > MAX_SUPERSAMPLE) {
        return invalid(format!(
            "supersample {k} must be 1 or even, from 2 to {MAX_SUPERSAMPLE} (the k/2 render must exist)"
        ));
    }
    if req.width.checked_mul(k).is_none() || req.height.checked_mul(k).is_none() {
        return invalid(format!(
            "{}x{} at k = {k} is too large",
            req.width, req.height
        ));
    }
    for (name, value) in &req.declares {
        let mut chars = name.chars();
        let identifier = chars
            .next()
            .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
            && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
        if !identifier {
            return invalid(format!("declare name {name:?} is not an identifier"));
        }
        if !value.is_finite() {
            return invalid(format!("declare {name} = {value} is not finite"));
        }
    }
    Ok(())
}

impl PovrayRunner<'_> {
    /// Runs POV-Ray at `factor` times the size and returns the block-averaged image and the
    /// wall time.
    fn render(
        &self,
        factor: u32,
        antialias: &[&str],
        threads: Option<usize>,
    ) -> Result<PovrayRun, StudyError> {
        let (width, height) = (self.req.width * factor, self.req.height * factor);
        let output_name = format!("render-{factor}.exr");
        // A file left by an earlier run must not pass for this run's output.
        let _ = std::fs::remove_file(self.dir.path().join(&output_name));
        let mut command = Command::new(&self.povray);
        // POV-Ray's default I/O policy lets it write in its working directory, so it runs
        // inside the temporary directory and writes there under a relative name.
        command
            .current_dir(self.dir.path())
            .args(&self.req.extra_args)
            .arg(format!("+I{}", self.scene.display()))
            .arg(format!("+O{output_name}"))
            .arg("+FE")
            .arg(format!("+W{width}"))
            .arg(format!("+H{height}"))
            // No display, no pause, no progress chatter (errors and warnings still arrive and
            // go into the error message); the statistics stream stays on for the times.
            .args(antialias)
            .args(["-D", "-P", "-GR"]);
        if let Some(n) = threads {
            command.arg(format!("+WT{}", n.max(1)));
        }
        for path in &self.include_paths {
            command.arg(format!("+L{}", path.display()));
        }
        if let Some(clock) = self.req.clock {
            command.arg(format!("+K{clock}"));
        }
        for (name, value) in &self.req.declares {
            // Rust prints f64 without exponents and with enough digits to round-trip.
            command.arg(format!("Declare={name}={value}"));
        }
        let start = Instant::now();
        let output = command.output().map_err(|source| StudyError::Io {
            path: self.povray.to_path_buf(),
            source,
        })?;
        let seconds = start.elapsed().as_secs_f64();
        let exr_path = output_file(self.dir.path(), &output_name);
        if !output.status.success() || !exr_path.is_file() {
            return Err(StudyError::PovrayFailed {
                scene: self.scene.to_path_buf(),
                status: if output.status.success() {
                    "no output file".to_string()
                } else {
                    output.status.to_string()
                },
                output: last_lines(&output.stdout, &output.stderr, ERROR_LINES),
            });
        }
        let file = read_exr(&exr_path)?;
        let expected = (width as usize, height as usize);
        if (file.image.width, file.image.height) != expected {
            return Err(StudyError::SizeMismatch {
                what: format!("povray's output {}", exr_path.display()),
                expected,
                found: (file.image.width, file.image.height),
            });
        }
        let image =
            file.image
                .downsample(factor as usize)
                .ok_or_else(|| StudyError::InvalidImage {
                    what: format!("povray's output {}", exr_path.display()),
                })?;
        Ok(PovrayRun {
            image,
            seconds,
            reported_seconds: reported_seconds(&String::from_utf8_lossy(&output.stderr)),
        })
    }
}

/// `name` in `dir`, or, when an INI made POV-Ray render an animation frame, the file it
/// named with the frame number inserted before the extension (`render-16001.exr`).
fn output_file(dir: &Path, name: &str) -> PathBuf {
    let exact = dir.join(name);
    if exact.is_file() {
        return exact;
    }
    let stem = name.trim_end_matches(".exr");
    std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|entry| entry.file_name().to_string_lossy().into_owned())
        .find(|file| {
            file.strip_prefix(stem)
                .and_then(|rest| rest.strip_suffix(".exr"))
                .is_some_and(|digits| {
                    !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit())
                })
        })
        .map_or(exact, |file| dir.join(file))
}

/// Sums the "(N seconds)" of POV-Ray's "... Time:" statistics lines (parse, bounding,
/// photons, radiosity, trace); the "using N thread(s) with N CPU-seconds" lines under them
/// are CPU time and are skipped.
pub fn reported_seconds(statistics: &str) -> Option<f64> {
    let mut total = None;
    for line in statistics.lines() {
        if !line.contains("Time:") {
            continue;
        }
        let Some(open) = line.rfind('(') else {
            continue;
        };
        let inside = &line[open + 1..];
        if let Some(value) = inside
            .strip_suffix("seconds)")
            .and_then(|v| v.trim().parse::<f64>().ok())
        {
            total = Some(total.unwrap_or(0.0) + value);
        }
    }
    total
}

/// The last `count` non-empty lines of POV-Ray's output (it writes most to stderr).
fn last_lines(stdout: &[u8], stderr: &[u8], count: usize) -> String {
    let text = format!(
        "{}\n{}",
        String::from_utf8_lossy(stdout),
        String::from_utf8_lossy(stderr)
    );
    let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    lines[lines.len().saturating_sub(count)..].join("\n")
}

#[cfg(test)]
#[path = "reference_tests.rs"]
mod tests;
