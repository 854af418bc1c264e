//! The corpus-wide comparison (issue 12): every POV-Ray example scene that penumbra parses is
//! rendered by penumbra with K seeds and by POV-Ray as a converged reference (k and k/2
//! times larger without anti-aliasing, as `penumbra reference` does), and judged with the
//! statistics of testing-statistics.md: pixel by pixel, or, where the scene's textures use
//! POV-Ray's noise, with a distribution test blind to the noise's phase (`judge`).
//!
//! References are cached outside git, keyed by a hash of the scene and the includes it
//! reads, the size, k and POV-Ray's version string (`scan::ReferenceKey`), so a rerun costs
//! only penumbra's renders. Every parse, render and reference runs as a child process with
//! a time limit (`exec`); a failure is a row, never the end of the sweep. `report` writes
//! the markdown table and the gallery of failures, after every scene, so an interrupted
//! sweep leaves a complete table whose unreached rows say "not measured yet".

pub mod ensemble;
pub mod exec;
pub mod judge;
pub mod known;
pub mod report;
pub mod scan;

pub use self::judge::{
    DistributionVerdict, Judgement, TestKind, distribution_test, judge, mean_image,
};

use super::converge::Log;
use super::media_quadrature;
use super::reference::MediaQuadrature;
use super::{StudyError, TempDir, read_reference};
use crate::output::{Image, read_exr};
use exec::{Ended, Finished, run_limited};
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// What to sweep and how.
#[derive(Debug, Clone, PartialEq)]
pub struct CorpusRequest {
    /// POV-Ray's example scenes (/usr/share/povray-3.7/scenes).
    pub scenes_dir: PathBuf,
    /// Library include folders, searched for the includes that enter the cache key and the
    /// noise scan (/usr/share/povray-3.7/include).
    pub include_dirs: Vec<PathBuf>,
    /// Measure only scenes whose relative path matches one of these comma-separated globs
    /// (every scene is still parsed).
    pub only: Option<String>,
    pub seeds: u32,
    pub spp: u32,
    pub width: u32,
    pub height: u32,
    /// k of the reference (the k/2 render is kept beside it).
    pub supersample: u32,
    /// The markdown table; failures' PNGs go to a folder named after it (docs/corpus/).
    pub out: PathBuf,
    /// Where references are cached.
    pub cache: PathBuf,
    /// The penumbra executable the children run.
    pub penumbra: PathBuf,
    pub timeouts: Timeouts,
    /// Measure in order of a 1-sample probe render's time, cheapest first, so that an
    /// interrupted sweep has measured as many scenes as it could (the table stays sorted by
    /// name).
    pub cheap_first: bool,
    /// Failures whose reason is written down (tests/corpus/known-differences.txt).
    pub known: Vec<known::Known>,
    /// Scenes judged over noise phases, with the anchor of the shift
    /// (tests/corpus/phase-ensemble.txt, `ensemble`).
    pub phase_ensemble: Vec<known::Known>,
}

/// Time limits in seconds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timeouts {
    pub parse: u64,
    /// Per penumbra replicate.
    pub render: u64,
    /// For POV-Ray's k and k/2 renders together.
    pub reference: u64,
}

impl Default for Timeouts {
    fn default() -> Self {
        Timeouts {
            parse: 30,
            render: 300,
            reference: 1200,
        }
    }
}

/// The outcome of `penumbra check` on a scene.
#[derive(Debug, Clone, PartialEq)]
pub enum ParseStatus {
    Parsed,
    /// A feature penumbra lacks; the diagnostic's first line.
    Unsupported(String),
    Error(String),
    Crash(String),
    TimedOut,
}

/// What became of a parsed scene.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    NotMeasured,
    RenderFailed(String),
    ReferenceFailed(String),
    Judged(Box<Judgement>),
}

/// One scene of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Path relative to the scenes folder.
    pub scene: String,
    pub parse: ParseStatus,
    pub test: TestKind,
    /// Both renderers read this INI with the scene, and render its first frame.
    pub ini: Option<PathBuf>,
    /// POV-Ray's reference at converged media quadrature, for scenes with media blocks.
    pub media: MediaQuadrature,
    pub outcome: Outcome,
    /// penumbra's K renders, wall time summed.
    pub penumbra_seconds: Option<f64>,
    /// POV-Ray's k render (from the cached reference).
    pub povray_seconds: Option<f64>,
    pub cached: bool,
    /// The reason written down for this scene's failure, if any.
    pub known: Option<String>,
    /// For scenes judged over noise phases: the text the shift goes after.
    pub phase_anchor: Option<String>,
}

impl Row {
    fn new(scene: &str) -> Row {
        Row {
            scene: scene.to_string(),
            parse: ParseStatus::TimedOut,
            test: TestKind::Pixel,
            ini: None,
            media: MediaQuadrature::AsWritten,
            outcome: Outcome::NotMeasured,
            penumbra_seconds: None,
            povray_seconds: None,
            cached: false,
            known: None,
            phase_anchor: None,
        }
    }
}

/// Parses every scene, measures the selected parsed ones, rewrites the report after each,
/// and returns the rows.
pub fn run(req: &CorpusRequest, log: &dyn Log) -> Result<Vec<Row>, StudyError> {
    let start = Instant::now();
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| StudyError::Io { path, source }
    };
    let scenes = scan::list_scenes(&req.scenes_dir).map_err(io(&req.scenes_dir))?;
    std::fs::create_dir_all(req.cache.join("references")).map_err(io(&req.cache))?;
    let version = exec::povray_version();
    let mut rows: Vec<Row> = scenes
        .iter()
        .map(|s| Row {
            known: known::reason(&req.known, s).map(str::to_string),
            phase_anchor: known::reason(&req.phase_ensemble, s).map(str::to_string),
            ..Row::new(s)
        })
        .collect();
    for row in &mut rows {
        prepare(req, row);
    }
    log.line(&format!(
        "{} scenes, {} parse; POV-Ray: {version}",
        rows.len(),
        rows.iter()
            .filter(|r| r.parse == ParseStatus::Parsed)
            .count()
    ));
    let context = report::Context {
        req,
        povray_version: &version,
        start,
    };
    report::write(&context, &rows, false)?;
    let mut order: Vec<usize> = (0..rows.len())
        .filter(|&i| rows[i].parse == ParseStatus::Parsed)
        .filter(|&i| {
            req.only.as_deref().is_none_or(|globs| {
                globs
                    .split(',')
                    .any(|g| scan::glob_match(g.trim(), &rows[i].scene))
            })
        })
        .collect();
    if req.cheap_first {
        let costs: Vec<(usize, f64)> = order.iter().map(|&i| (i, probe(req, &rows[i]))).collect();
        order = sorted_by_cost(costs);
        log.line(&format!(
            "{} scenes to measure, cheapest first",
            order.len()
        ));
    }
    for i in order {
        measure(req, &version, &mut rows[i]);
        log.line(&format!(
            "{}: {}",
            rows[i].scene,
            report::result_text(&rows[i])
        ));
        if let Outcome::Judged(j) = &rows[i].outcome
            && !j.passes()
        {
            log.line(&format!("  {}", j.summary()));
        }
        report::write(&context, &rows, false)?;
    }
    report::write(&context, &rows, true)?;
    Ok(rows)
}

/// Parses the scene in a child process and classifies its textures. A scene with an INI
/// is parsed as it is rendered, with the INI and its first frame (the portfolio scenes
/// index their arrays by frame_number, which is 0 without it).
fn prepare(req: &CorpusRequest, row: &mut Row) {
    let path = req.scenes_dir.join(&row.scene);
    let folder = path.parent().unwrap_or(Path::new(".")).to_path_buf();
    row.ini = scan::ini_for(&path);
    // Scenes that write data files (html_gen.inc, makestacks.inc) write into a scratch
    // folder, as POV-Ray writes into its working folder.
    let scratch = TempDir::new("corpus-check").ok();
    let mut args: Vec<OsString> = match &row.ini {
        Some(ini) => {
            let mut library = OsString::from("+L");
            library.push(&folder);
            let mut a: Vec<OsString> = vec!["render".into(), ini.into(), path.clone().into()];
            a.extend(scan::first_frame_args(ini).into_iter().map(OsString::from));
            a.extend(["+W1".into(), "+H1".into(), "-F".into(), library]);
            a.extend(["--spp".into(), "1".into(), "--quiet".into()]);
            a
        }
        None => vec![
            "check".into(),
            "-L".into(),
            folder.into(),
            path.clone().into(),
        ],
    };
    if let Some(dir) = &scratch {
        args.extend(["--allow-write".into(), dir.path().into()]);
    }
    let run = run_limited(&req.penumbra.clone().into(), &args, req.timeouts.parse);
    row.parse = parse_status(&run);
    if std::fs::read(&path).is_ok_and(|text| media_quadrature::has_media(&text)) {
        row.media = MediaQuadrature::Converged;
    }
    if let Ok(files) = scan::sources(&path, &req.include_dirs) {
        let words = scan::noise_words(&files);
        if !words.is_empty() {
            row.test = TestKind::Distribution(words);
        }
    }
}

pub fn parse_status(run: &Finished) -> ParseStatus {
    let message = run.message();
    match &run.ended {
        Ended::Success => ParseStatus::Parsed,
        Ended::TimedOut => ParseStatus::TimedOut,
        Ended::Failed(_) if run.panicked() || run.stderr.contains("signal") => {
            ParseStatus::Crash(message)
        }
        Ended::Failed(_) if message.contains("unsupported") => ParseStatus::Unsupported(message),
        Ended::Failed(status) if message.is_empty() => ParseStatus::Error(status.clone()),
        Ended::Failed(_) => ParseStatus::Error(message),
    }
}

/// Renders the replicates, fetches or renders the reference, and judges.
fn measure(req: &CorpusRequest, version: &str, row: &mut Row) {
    let path = req.scenes_dir.join(&row.scene);
    let replicates = match render_replicates(req, &path, row) {
        Ok(images) => images,
        Err(message) => {
            row.outcome = Outcome::RenderFailed(message);
            return;
        }
    };
    let reference = match cached_reference(req, version, &path, row) {
        Ok(reference) => reference,
        Err(message) => {
            row.outcome = Outcome::ReferenceFailed(message);
            return;
        }
    };
    row.povray_seconds = Some(reference.povray_seconds);
    let ensemble = match row.phase_anchor.clone() {
        Some(anchor) => match phase_ensemble(req, version, &path, row, &anchor) {
            Ok(verdict) => Some(verdict),
            Err(message) => {
                row.outcome = Outcome::RenderFailed(format!("phase ensemble: {message}"));
                return;
            }
        },
        None => None,
    };
    row.outcome = match judge(&row.test, &replicates, &reference) {
        Ok(mut j) => {
            j.ensemble = ensemble;
            if !j.passes() {
                let mean = mean_image(&replicates);
                let _ = report::write_gallery_image(req, &row.scene, &mean, &reference.full);
            }
            Outcome::Judged(Box::new(j))
        }
        Err(e) => Outcome::RenderFailed(format!("cannot judge: {e}")),
    };
}

/// Renders `ensemble::PHASES` shifted copies of the scene with both renderers (penumbra one
/// seed each at a quarter of the sample count, POV-Ray a cached reference each) and runs the
/// phase-ensemble test.
fn phase_ensemble(
    req: &CorpusRequest,
    version: &str,
    path: &Path,
    row: &Row,
    anchor: &str,
) -> Result<DistributionVerdict, String> {
    let text = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let folder = path.parent().unwrap_or(Path::new("."));
    let dir = TempDir::new("corpus-phase").map_err(|e| format!("temporary folder: {e}"))?;
    let copy = dir.path().join(path.file_name().unwrap_or_default());
    let (mut penumbra, mut povray) = (Vec::new(), Vec::new());
    for k in 0..ensemble::PHASES {
        let shifted = ensemble::shifted(&text, anchor, k)
            .ok_or_else(|| format!("the anchor `{anchor}` is not in the scene"))?;
        std::fs::write(&copy, shifted).map_err(|e| format!("{}: {e}", copy.display()))?;
        let source = Source {
            scene: &copy,
            folder,
        };
        let replicate = Replicate {
            seed: 200 + k as u64,
            spp: (req.spp / 4).max(1),
        };
        penumbra.push(render_one(req, source, row.ini.as_deref(), replicate)?.0);
        let job = ReferenceJob {
            original: path,
            source,
            supersample: ensemble::PHASE_SUPERSAMPLE,
            variant: Some(format!("phase {k} after {anchor}")),
        };
        povray.push(reference_of(req, version, row, &job)?.0);
    }
    ensemble::ensemble_test(&penumbra, &povray).map_err(|e| e.to_string())
}

/// Indices sorted by cost, ascending (ties by index).
pub fn sorted_by_cost(mut costs: Vec<(usize, f64)>) -> Vec<usize> {
    costs.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
    costs.into_iter().map(|(i, _)| i).collect()
}

/// Wall time of one 1-sample render of the scene (parse included): the cost estimate of
/// `cheap_first`. A failing probe costs 0 (its scene fails fast when measured).
fn probe(req: &CorpusRequest, row: &Row) -> f64 {
    let path = req.scenes_dir.join(&row.scene);
    let Ok(dir) = TempDir::new("corpus-probe") else {
        return 0.0;
    };
    let args: Vec<OsString> = vec![
        "render".into(),
        path.clone().into(),
        "--output".into(),
        dir.path().join("probe.exr").into(),
        "--width".into(),
        req.width.to_string().into(),
        "--height".into(),
        req.height.to_string().into(),
        "--spp".into(),
        "1".into(),
        "--quiet".into(),
        "-L".into(),
        scene_folder(&path),
        "--allow-write".into(),
        dir.path().into(),
    ];
    let run = run_limited(&req.penumbra.clone().into(), &args, req.timeouts.render);
    match run.ended {
        Ended::Success => run.seconds,
        Ended::TimedOut => f64::INFINITY,
        Ended::Failed(_) => 0.0,
    }
}

fn scene_folder(path: &Path) -> OsString {
    path.parent().unwrap_or(Path::new(".")).as_os_str().into()
}

/// K `penumbra render` children, seeds 100.. (as tests/povray_examples.rs uses).
fn render_replicates(
    req: &CorpusRequest,
    path: &Path,
    row: &mut Row,
) -> Result<Vec<Image>, String> {
    let folder = path.parent().unwrap_or(Path::new("."));
    let source = Source {
        scene: path,
        folder,
    };
    let mut images = Vec::new();
    let mut seconds = 0.0;
    for k in 0..req.seeds {
        let replicate = Replicate {
            seed: 100 + u64::from(k),
            spp: req.spp,
        };
        let (image, time) = render_one(req, source, row.ini.as_deref(), replicate)?;
        images.push(image);
        seconds += time;
    }
    row.penumbra_seconds = Some(seconds);
    Ok(images)
}

/// One `penumbra render` child: its image and wall time.
fn render_one(
    req: &CorpusRequest,
    source: Source,
    ini: Option<&Path>,
    replicate: Replicate,
) -> Result<(Image, f64), String> {
    let dir = TempDir::new("corpus").map_err(|e| format!("temporary folder: {e}"))?;
    // A folder of its own: with an INI that animates, the frame's number goes into the
    // file's name.
    let out_dir = dir.path().join("out");
    std::fs::create_dir_all(&out_dir).map_err(|e| format!("temporary folder: {e}"))?;
    let args = replicate_args(req, source, ini, &out_dir, dir.path(), replicate);
    let run = run_limited(&req.penumbra.clone().into(), &args, req.timeouts.render);
    match &run.ended {
        Ended::Success => {}
        Ended::TimedOut => {
            return Err(format!("penumbra timed out ({} s)", req.timeouts.render));
        }
        Ended::Failed(_) if run.panicked() => {
            return Err(format!("penumbra panicked: {}", run.message()));
        }
        Ended::Failed(status) => {
            return Err(format!("penumbra failed ({status}): {}", run.message()));
        }
    }
    let output = single_file(&out_dir)?;
    let image = read_exr(&output).map_err(|e| e.to_string())?.image;
    Ok((image, run.seconds))
}

/// What a render or a reference reads: the scene file (the original, or a rewritten copy
/// in a scratch folder) and the folder its includes and data files are found in.
#[derive(Clone, Copy)]
struct Source<'a> {
    scene: &'a Path,
    folder: &'a Path,
}

/// One penumbra render of a source.
#[derive(Clone, Copy)]
struct Replicate {
    seed: u64,
    spp: u32,
}

/// One replicate's command line. A scene with an INI is rendered the POV-Ray way, the INI
/// before the scene (whose path then wins over the INI's relative Input_File_Name) and only
/// its first frame, as POV-Ray renders the reference: the same clock, clock_delta and
/// frame_number.
fn replicate_args(
    req: &CorpusRequest,
    source: Source,
    ini: Option<&Path>,
    out_dir: &Path,
    scratch: &Path,
    replicate: Replicate,
) -> Vec<OsString> {
    let mut args: Vec<OsString> = vec!["render".into()];
    let own = [
        "--spp".into(),
        replicate.spp.to_string().into(),
        "--seed".into(),
        replicate.seed.to_string().into(),
        "--quiet".into(),
        "--allow-write".into(),
        scratch.into(),
    ];
    match ini {
        Some(ini) => {
            args.push(ini.into());
            args.push(source.scene.into());
            args.extend(scan::first_frame_args(ini).into_iter().map(OsString::from));
            let mut output = OsString::from("+O");
            output.push(out_dir.join("image.exr"));
            let mut library = OsString::from("+L");
            library.push(source.folder);
            args.extend([
                format!("+W{}", req.width).into(),
                format!("+H{}", req.height).into(),
                "+FE".into(),
                output,
                library,
            ]);
        }
        None => args.extend([
            source.scene.into(),
            "--output".into(),
            out_dir.join("image.exr").into(),
            "--width".into(),
            req.width.to_string().into(),
            "--height".into(),
            req.height.to_string().into(),
            "-L".into(),
            source.folder.into(),
        ]),
    }
    args.extend(own);
    args
}

/// The one image a replicate wrote into its folder.
fn single_file(dir: &Path) -> Result<PathBuf, String> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| e.to_string())?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "exr"))
        .collect();
    match files.len() {
        1 => Ok(files.remove(0)),
        n => Err(format!("penumbra wrote {n} images where one was expected")),
    }
}

/// The scene's reference from the cache, or rendered by a `penumbra reference` child and
/// stored there.
fn cached_reference(
    req: &CorpusRequest,
    version: &str,
    path: &Path,
    row: &mut Row,
) -> Result<super::Reference, String> {
    let folder = path.parent().unwrap_or(Path::new("."));
    let source = Source {
        scene: path,
        folder,
    };
    let job = ReferenceJob {
        original: path,
        source,
        supersample: req.supersample,
        variant: None,
    };
    let (reference, cached) = reference_of(req, version, row, &job)?;
    row.cached = cached;
    Ok(reference)
}

/// A POV-Ray reference to fetch or render: of `source`, cached under the key of `original`
/// (the scene file and its includes) and the `variant` (what was changed in the copy).
struct ReferenceJob<'a> {
    original: &'a Path,
    source: Source<'a>,
    supersample: u32,
    variant: Option<String>,
}

/// The job's reference and whether it came from the cache.
fn reference_of(
    req: &CorpusRequest,
    version: &str,
    row: &Row,
    job: &ReferenceJob,
) -> Result<(super::Reference, bool), String> {
    let files = scan::sources(job.original, &req.include_dirs).map_err(|e| e.to_string())?;
    let extra_args = row.ini.as_deref().map(scan::ini_args).unwrap_or_default();
    let key_args: Vec<String> = extra_args
        .iter()
        .cloned()
        .chain(job.variant.clone())
        .collect();
    let key = scan::ReferenceKey {
        files: &files,
        width: req.width,
        height: req.height,
        supersample: job.supersample,
        povray_version: version,
        extra_args: &key_args,
        media: row.media,
    };
    let cached = req.cache.join("references").join(key.file_name(&row.scene));
    if let Ok(reference) = read_reference(&cached) {
        return Ok((reference, true));
    }
    let partial = cached.with_extension("partial.exr");
    let mut args: Vec<OsString> = vec![
        "reference".into(),
        job.source.scene.into(),
        "--output".into(),
        partial.clone().into(),
        "--width".into(),
        req.width.to_string().into(),
        "--height".into(),
        req.height.to_string().into(),
        "--supersample".into(),
        job.supersample.to_string().into(),
        "-L".into(),
        job.source.folder.into(),
    ];
    args.extend(
        extra_args
            .iter()
            .map(|a| format!("--povray-arg={a}").into()),
    );
    if row.media == MediaQuadrature::Converged {
        args.push("--converged-media".into());
    }
    let run = run_limited(&req.penumbra.clone().into(), &args, req.timeouts.reference);
    match run.ended {
        Ended::Success => {}
        Ended::TimedOut => {
            return Err(format!("POV-Ray timed out ({} s)", req.timeouts.reference));
        }
        Ended::Failed(_) => return Err(format!("POV-Ray failed: {}", povray_error(&run))),
    }
    std::fs::rename(&partial, &cached).map_err(|e| e.to_string())?;
    let reference = read_reference(&cached).map_err(|e| e.to_string())?;
    Ok((reference, false))
}

/// POV-Ray's own error line, when `penumbra reference` relays one.
fn povray_error(run: &Finished) -> String {
    run.stderr
        .lines()
        .map(str::trim)
        .find(|l| l.contains("Parse Error") || l.contains("Error:"))
        .map_or_else(|| run.message(), str::to_string)
}

#[cfg(test)]
mod tests;
