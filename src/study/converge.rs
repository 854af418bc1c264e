//! `penumbra converge`: error against time for penumbra at several sample counts and for
//! POV-Ray at its quality settings, on the same scene, size and reference.
//!
//! Each sample count is rendered with K seeds, so that every row carries the noise sqrt(V)
//! and the bias sqrt(B) apart, not only an RMSE that mixes them. Rows are appended to the
//! CSV as soon as they are measured: an interrupted run keeps what it has.

use super::charts::{self, BandPoint, Curve, ErrorChart, Marker};
use super::metrics;
use super::reference::{ReferenceRequest, read_reference, render_povray};
use super::{Reference, StudyError};
use crate::lang::{LoadOptions, load_scene};
use crate::output::Image;
use crate::render::{LightSamples, RenderOptions};
use crate::scene::Scene;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// POV-Ray's quality ladder: no anti-aliasing, then adaptive supersampling, then
/// recursive adaptive supersampling at depths 3 and 4.
pub const POVRAY_SETTINGS: [(&str, &[&str]); 4] = [
    ("-A", &["-A"]),
    ("+A0.3", &["+A0.3"]),
    ("+AM2 +R3", &["+A0.3", "+AM2", "+R3"]),
    ("+AM2 +R4", &["+A0.3", "+AM2", "+R4"]),
];

/// The error targets of the speed-up table.
pub const DEFAULT_TARGETS: [f64; 2] = [0.01, 0.005];

/// Seeds of replicate k are `SEED_BASE + k`, the same at every sample count.
const SEED_BASE: u64 = 1;

#[derive(Debug, Clone, PartialEq)]
pub struct ConvergeRequest {
    pub scene: PathBuf,
    pub declares: Vec<(String, f64)>,
    pub include_paths: Vec<PathBuf>,
    /// A reference written by `penumbra reference`; it fixes the image size.
    pub reference: PathBuf,
    /// Samples per pixel; fractional counts (adaptive only) are averages.
    pub spp: Vec<f64>,
    /// K, the replicates per sample count; at least 2 to split noise from bias.
    pub seeds: u32,
    pub povray: bool,
    pub output_dir: PathBuf,
    /// For penumbra and POV-Ray alike; `None`: every core.
    pub threads: Option<usize>,
    pub stratified: bool,
    pub targets: Vec<f64>,
    /// Shadow rays per area light per shading point.
    pub light_samples: LightSamples,
    /// Per-pixel adaptive sample counts (`--adaptive`).
    pub adaptive: bool,
}

/// One sample count: medians and ranges over the K seeds, and the split.
#[derive(Debug, Clone, PartialEq)]
pub struct PenumbraRow {
    pub spp: f64,
    /// Wall time of one replicate: scene load (parse) plus render, median over seeds.
    pub seconds: f64,
    pub seconds_low: f64,
    pub seconds_high: f64,
    /// RMSE of one replicate against the reference: median, lowest, highest over seeds.
    pub rmse: f64,
    pub rmse_low: f64,
    pub rmse_high: f64,
    /// sqrt(V).
    pub noise: f64,
    /// sqrt(B) on 4x4 blocks, the reference's own error subtracted.
    pub bias: f64,
    /// sqrt(max(mean MSE - V, 0)): the floor RMSE tends to per pixel, where the reference's
    /// own per-pixel error at edges also counts.
    pub pixel_floor: f64,
    pub tiles_failed: usize,
    pub tiles_tested: usize,
}

#[derive(Debug, Clone, PartialEq)]
pub struct PovrayRow {
    pub setting: String,
    /// Process wall time, parse included.
    pub seconds: f64,
    /// POV-Ray's own reported parse + render time (falls back to `seconds`): its process
    /// spends a fixed ~0.6 s starting and stopping, which at study sizes would dominate.
    pub net_seconds: f64,
    pub rmse: f64,
}

/// When a method first reaches a target error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reach {
    /// Interpolated on the log-log curve between two measurements.
    At(f64),
    /// Already below the target at the first (fastest) measurement.
    AtMost(f64),
    /// Never at or below the target; the lowest error measured.
    NotReached { best: f64 },
}

impl Reach {
    pub fn seconds(&self) -> Option<f64> {
        match self {
            Reach::At(s) | Reach::AtMost(s) => Some(*s),
            Reach::NotReached { .. } => None,
        }
    }
}

impl std::fmt::Display for Reach {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Reach::At(s) => write!(f, "{} s", seconds3(*s)),
            Reach::AtMost(s) => write!(f, "<= {} s", seconds3(*s)),
            Reach::NotReached { best } => write!(f, "not reached (best {best:.5})"),
        }
    }
}

fn seconds3(s: f64) -> String {
    if s >= 10.0 {
        format!("{s:.1}")
    } else if s >= 0.1 {
        format!("{s:.2}")
    } else {
        format!("{s:.3}")
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct TargetRow {
    pub target: f64,
    pub penumbra: Reach,
    pub povray: Option<Reach>,
}

impl TargetRow {
    /// POV-Ray's time over penumbra's; a lower bound (`true`) when POV-Ray never got there.
    pub fn speed_up(&self) -> Option<(f64, bool)> {
        let pen = self.penumbra.seconds()?;
        match self.povray? {
            Reach::At(p) | Reach::AtMost(p) => Some((p / pen, false)),
            Reach::NotReached { .. } => None,
        }
    }

    fn speed_up_text(&self, povray_max_seconds: f64) -> String {
        match (self.penumbra.seconds(), self.povray) {
            (Some(_), Some(Reach::NotReached { .. })) => {
                let pen = self.penumbra.seconds().unwrap_or(f64::NAN);
                format!("> {:.1}x", povray_max_seconds / pen)
            }
            (Some(_), Some(_)) => self
                .speed_up()
                .map(|(x, _)| format!("{x:.1}x"))
                .unwrap_or_else(|| "-".into()),
            _ => "-".into(),
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct ConvergeReport {
    pub scene: String,
    pub width: usize,
    pub height: usize,
    pub threads: usize,
    pub stratified: bool,
    pub rows: Vec<PenumbraRow>,
    pub povray: Vec<PovrayRow>,
    pub targets: Vec<TargetRow>,
    /// Noise slope d log sqrt(V) / d log spp, least squares over the rows.
    pub noise_slope: Option<f64>,
    /// POV-Ray's time for the reference itself (k x k samples per pixel).
    pub reference_seconds: f64,
}

impl ConvergeReport {
    /// sqrt(B) at the largest sample count: the best estimate of the bias floor.
    pub fn bias_floor(&self) -> Option<f64> {
        self.rows.last().map(|r| r.bias)
    }
}

/// Reports progress lines, for runs that take minutes.
pub trait Log {
    fn line(&self, text: &str);
}

impl Log for () {
    fn line(&self, _: &str) {}
}

fn validate(req: &ConvergeRequest) -> Result<(), StudyError> {
    let invalid = |m: String| Err(StudyError::InvalidRequest(m));
    if req.spp.is_empty() || !req.spp.iter().all(|&n| crate::render::spp_in_range(n)) {
        return invalid("--spp needs one or more sample counts from 1 to 1048576".into());
    }
    if !req.adaptive && req.spp.iter().any(|n| n.fract() != 0.0) {
        return invalid(
            "a fractional --spp is an adaptive render's average: add --adaptive".into(),
        );
    }
    if req.seeds < 2 {
        return Err(StudyError::TooFewReplicates {
            found: req.seeds as usize,
        });
    }
    if req.threads == Some(0) {
        return invalid("--threads must be at least 1".into());
    }
    if let Some(t) = req.targets.iter().find(|t| !(t.is_finite() && **t > 0.0)) {
        return invalid(format!("target error {t} must be positive"));
    }
    Ok(())
}

/// What every measurement of one study shares: the request, the loaded scene and its
/// reference, and how to render and report.
struct Study<'a> {
    req: &'a ConvergeRequest,
    reference: Reference,
    scene: Scene,
    /// Parse time, counted in each replicate's time.
    load_seconds: f64,
    threads: usize,
    /// The scene's file stem, which starts every progress line.
    name: String,
    log: &'a dyn Log,
}

/// Runs the study, writing `converge.csv`, `error_vs_time.{svg,png}`,
/// `error_vs_spp.{svg,png}` and `summary.md` into the output folder.
pub fn converge(req: &ConvergeRequest, log: &dyn Log) -> Result<ConvergeReport, StudyError> {
    let study = prepare(req, log)?;
    let mut csv = Csv::create(&req.output_dir.join("converge.csv"))?;
    let rows = measure_penumbra(&study, &mut csv)?;
    let povray = if req.povray {
        measure_povray(&study, &mut csv)?
    } else {
        Vec::new()
    };
    let report = build_report(study, rows, povray);
    write_outputs(&req.output_dir, &report)?;
    Ok(report)
}

/// Checks the request, reads the reference, creates the output folder and loads the scene.
fn prepare<'a>(req: &'a ConvergeRequest, log: &'a dyn Log) -> Result<Study<'a>, StudyError> {
    validate(req)?;
    // Fail before minutes of rendering, not after.
    if req.povray {
        super::reference::find_povray()?;
    }
    let reference = read_reference(&req.reference)?;
    let (width, height) = (reference.full.width, reference.full.height);
    let threads = req.threads.unwrap_or_else(|| {
        std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
    });
    let name = req
        .scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "scene".into());
    std::fs::create_dir_all(&req.output_dir).map_err(|source| StudyError::Io {
        path: req.output_dir.clone(),
        source,
    })?;
    let (scene, load_seconds) = load(req, width, height)?;
    Ok(Study {
        req,
        reference,
        scene,
        load_seconds,
        threads,
        name,
        log,
    })
}

/// One row per distinct sample count, in increasing order, each appended to the CSV.
fn measure_penumbra(study: &Study, csv: &mut Csv) -> Result<Vec<PenumbraRow>, StudyError> {
    let mut spp = study.req.spp.clone();
    spp.sort_by(f64::total_cmp);
    spp.dedup();
    let mut rows = Vec::new();
    for &n in &spp {
        let row = measure_spp(study, n)?;
        csv.penumbra(&row)?;
        study.log.line(&format!(
            "{}: spp {n}: {} s, RMSE {:.5} [{:.5}, {:.5}], noise {:.5}, bias {:.5}, tiles failed {}/{}",
            study.name,
            seconds3(row.seconds),
            row.rmse,
            row.rmse_low,
            row.rmse_high,
            row.noise,
            row.bias,
            row.tiles_failed,
            row.tiles_tested
        ));
        rows.push(row);
    }
    Ok(rows)
}

/// One row per POV-Ray quality setting, each appended to the CSV.
fn measure_povray(study: &Study, csv: &mut Csv) -> Result<Vec<PovrayRow>, StudyError> {
    let (req, name) = (study.req, &study.name);
    let request = ReferenceRequest {
        scene: req.scene.clone(),
        width: study.reference.full.width as u32,
        height: study.reference.full.height as u32,
        supersample: 2,
        declares: req.declares.clone(),
        include_paths: req.include_paths.clone(),
        clock: None,
        extra_args: Vec::new(),
        // POV-Ray's speed is charted as users run it, with the scene's own quadrature.
        media: crate::study::reference::MediaQuadrature::AsWritten,
    };
    let mut povray = Vec::new();
    for (setting, args) in POVRAY_SETTINGS {
        study.log.line(&format!("{name}: POV-Ray {setting} ..."));
        let run = render_povray(&request, args, Some(study.threads))?;
        let rmse = metrics::rmse(&run.image, &study.reference.full)?;
        let row = PovrayRow {
            setting: setting.to_string(),
            seconds: run.seconds,
            // Never zero, so that it stays on a log axis.
            net_seconds: run.reported_seconds.unwrap_or(run.seconds).max(1e-3),
            rmse,
        };
        csv.povray(&row)?;
        study.log.line(&format!(
            "{name}: POV-Ray {setting}: {} s process, {} s parse + render, RMSE {rmse:.5}",
            seconds3(row.seconds),
            seconds3(row.net_seconds)
        ));
        povray.push(row);
    }
    Ok(povray)
}

/// The measurements with what is derived from them: times to reach the targets and the
/// noise slope.
fn build_report(study: Study, rows: Vec<PenumbraRow>, povray: Vec<PovrayRow>) -> ConvergeReport {
    let req = study.req;
    let penumbra_points: Vec<(f64, f64)> = rows.iter().map(|r| (r.seconds, r.rmse)).collect();
    let povray_points: Vec<(f64, f64)> = povray.iter().map(|r| (r.net_seconds, r.rmse)).collect();
    let targets = req
        .targets
        .iter()
        .map(|&target| TargetRow {
            target,
            penumbra: time_to_reach(&penumbra_points, target),
            povray: req.povray.then(|| time_to_reach(&povray_points, target)),
        })
        .collect();
    let noise_points: Vec<(f64, f64)> = rows.iter().map(|r| (r.spp, r.noise)).collect();
    ConvergeReport {
        scene: study.name,
        width: study.reference.full.width,
        height: study.reference.full.height,
        threads: study.threads,
        stratified: req.stratified,
        rows,
        povray,
        targets,
        noise_slope: log_log_slope(&noise_points),
        reference_seconds: study.reference.povray_seconds,
    }
}

/// The charts, `summary.md` and `speedup_row.md` (the CSV is written as rows come in).
fn write_outputs(dir: &Path, report: &ConvergeReport) -> Result<(), StudyError> {
    write_charts(dir, report)?;
    let summary = dir.join("summary.md");
    std::fs::write(&summary, summary_markdown(report)).map_err(|source| StudyError::Io {
        path: summary,
        source,
    })?;
    let row = dir.join("speedup_row.md");
    std::fs::write(&row, speed_up_cells(report))
        .map_err(|source| StudyError::Io { path: row, source })
}

fn load(req: &ConvergeRequest, width: usize, height: usize) -> Result<(Scene, f64), StudyError> {
    let options = LoadOptions {
        declares: req.declares.clone(),
        include_paths: req.include_paths.clone(),
        image_width: width as u32,
        image_height: height as u32,
        ..LoadOptions::default()
    };
    let start = Instant::now();
    let loaded = load_scene(&req.scene, &options).map_err(|d| StudyError::Scene(d.to_string()))?;
    Ok((loaded.scene, start.elapsed().as_secs_f64()))
}

/// K replicates at `spp` samples per pixel, seeds `SEED_BASE + k`, folded into one row.
fn measure_spp(study: &Study, spp: f64) -> Result<PenumbraRow, StudyError> {
    let (req, reference) = (study.req, &study.reference);
    let mut images = Vec::new();
    let mut seconds = Vec::new();
    let mut rmse = Vec::new();
    for k in 0..u64::from(req.seeds) {
        let options = RenderOptions {
            width: reference.full.width,
            height: reference.full.height,
            samples_per_pixel: spp.ceil() as u32,
            average_spp: (spp.fract() != 0.0).then_some(spp),
            seed: SEED_BASE + k,
            threads: Some(study.threads),
            stratified: req.stratified,
            light_samples: req.light_samples,
            adaptive: req.adaptive,
            ..RenderOptions::default()
        };
        let start = Instant::now();
        let (image, _) = crate::render_scene(&study.scene, &options, &())
            .map_err(|e| StudyError::Render(e.to_string()))?;
        let s = study.load_seconds + start.elapsed().as_secs_f64();
        let e = metrics::rmse(&image, &reference.full)?;
        study.log.line(&format!(
            "{}: spp {spp}, seed {}/{}: {} s, RMSE {e:.5}",
            study.name,
            k + 1,
            req.seeds,
            seconds3(s)
        ));
        seconds.push(s);
        rmse.push(e);
        images.push(image);
    }
    row_from_replicates(spp, &images, &seconds, &rmse, reference)
}

fn row_from_replicates(
    spp: f64,
    images: &[Image],
    seconds: &[f64],
    rmse: &[f64],
    reference: &Reference,
) -> Result<PenumbraRow, StudyError> {
    let verdict = metrics::evaluate(images, &reference.full, &reference.half)?;
    let mean_mse = rmse.iter().map(|e| e * e).sum::<f64>() / rmse.len() as f64;
    let v = verdict.sqrt_v * verdict.sqrt_v;
    let (s_med, s_lo, s_hi) = median_range(seconds);
    let (e_med, e_lo, e_hi) = median_range(rmse);
    Ok(PenumbraRow {
        spp,
        seconds: s_med,
        seconds_low: s_lo,
        seconds_high: s_hi,
        rmse: e_med,
        rmse_low: e_lo,
        rmse_high: e_hi,
        noise: verdict.sqrt_v,
        bias: verdict.sqrt_b,
        pixel_floor: (mean_mse - v).max(0.0).sqrt(),
        tiles_failed: verdict.tiles.failed(),
        tiles_tested: verdict.tiles.tested,
    })
}

/// Median, lowest and highest; NaN for an empty slice.
pub fn median_range(values: &[f64]) -> (f64, f64, f64) {
    if values.is_empty() {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    let median = if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    };
    (median, v[0], v[n - 1])
}

/// Least-squares slope of log y against log x over the points with both positive.
pub fn log_log_slope(points: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0 && x.is_finite() && y.is_finite())
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    if logs.len() < 2 {
        return None;
    }
    let n = logs.len() as f64;
    let mx = logs.iter().map(|p| p.0).sum::<f64>() / n;
    let my = logs.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

/// The earliest time at which (seconds, error) measurements reach `target`, interpolating
/// linearly in log-log between the last point above and the first at or below it. Only the
/// lower envelope counts (the best error reached by each time), since a slower setting that
/// is no better would never be chosen.
pub fn time_to_reach(points: &[(f64, f64)], target: f64) -> Reach {
    let mut sorted: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|(s, e)| *s > 0.0 && *e > 0.0 && s.is_finite() && e.is_finite())
        .collect();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut envelope: Vec<(f64, f64)> = Vec::new();
    for p in sorted {
        if envelope.last().is_none_or(|last| p.1 < last.1) {
            envelope.push(p);
        }
    }
    let Some(first) = envelope.first() else {
        return Reach::NotReached { best: f64::NAN };
    };
    if first.1 <= target {
        return Reach::AtMost(first.0);
    }
    for pair in envelope.windows(2) {
        let ((t0, e0), (t1, e1)) = (pair[0], pair[1]);
        if e1 <= target {
            let f = (target.ln() - e0.ln()) / (e1.ln() - e0.ln());
            return Reach::At((t0.ln() + f * (t1.ln() - t0.ln())).exp());
        }
    }
    Reach::NotReached {
        best: envelope.last().map_or(f64::NAN, |p| p.1),
    }
}

/// Appends rows as they are measured and flushes each, so an interrupted run keeps them.
struct Csv {
    file: std::fs::File,
    path: PathBuf,
}

/// `seconds` is what the charts and the time-to-target table use: penumbra's load and
/// render, POV-Ray's process time less its start-up; `process_seconds` is POV-Ray's whole
/// process time (penumbra's rows repeat `seconds`).
const CSV_HEADER: &str = "method,setting,spp,seconds,seconds_low,seconds_high,rmse,rmse_low,rmse_high,noise,bias,pixel_floor,tiles_failed,tiles_tested,process_seconds";

impl Csv {
    fn create(path: &Path) -> Result<Csv, StudyError> {
        let file = std::fs::File::create(path).map_err(|source| StudyError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let mut csv = Csv {
            file,
            path: path.to_path_buf(),
        };
        csv.line(CSV_HEADER)?;
        Ok(csv)
    }

    fn line(&mut self, text: &str) -> Result<(), StudyError> {
        writeln!(self.file, "{text}")
            .and_then(|()| self.file.flush())
            .map_err(|source| StudyError::Io {
                path: self.path.clone(),
                source,
            })
    }

    fn penumbra(&mut self, r: &PenumbraRow) -> Result<(), StudyError> {
        self.line(&format!(
            "penumbra,,{},{:.6},{:.6},{:.6},{:.7},{:.7},{:.7},{:.7},{:.7},{:.7},{},{},{:.6}",
            r.spp,
            r.seconds,
            r.seconds_low,
            r.seconds_high,
            r.rmse,
            r.rmse_low,
            r.rmse_high,
            r.noise,
            r.bias,
            r.pixel_floor,
            r.tiles_failed,
            r.tiles_tested,
            r.seconds
        ))
    }

    fn povray(&mut self, r: &PovrayRow) -> Result<(), StudyError> {
        self.line(&format!(
            "povray,{},,{:.6},{:.6},{:.6},{:.7},{:.7},{:.7},,,,,,{:.6}",
            r.setting,
            r.net_seconds,
            r.net_seconds,
            r.net_seconds,
            r.rmse,
            r.rmse,
            r.rmse,
            r.seconds
        ))
    }
}

fn write_charts(dir: &Path, report: &ConvergeReport) -> Result<(), StudyError> {
    let floors = floors(report);
    charts::write_error_chart(
        &dir.join("error_vs_time"),
        &time_chart(report, floors.clone()),
    )?;
    charts::write_error_chart(&dir.join("error_vs_spp"), &spp_chart(report, floors))
}

fn band(x: f64, y: f64, low: f64, high: f64) -> BandPoint {
    BandPoint { x, y, low, high }
}

/// The bias and the per-pixel floor at the largest sample count, drawn on both charts.
fn floors(report: &ConvergeReport) -> Vec<(String, f64)> {
    vec![
        (
            "penumbra bias sqrt(B)".to_string(),
            report.bias_floor().unwrap_or(0.0),
        ),
        (
            "per-pixel floor sqrt(MSE - V)".to_string(),
            report.rows.last().map_or(0.0, |r| r.pixel_floor),
        ),
    ]
}

/// `error_vs_time`: penumbra's RMSE and noise against seconds, POV-Ray's settings as markers.
fn time_chart(report: &ConvergeReport, floors: Vec<(String, f64)>) -> ErrorChart {
    let rmse_time: Vec<BandPoint> = report
        .rows
        .iter()
        .map(|r| band(r.seconds, r.rmse, r.rmse_low, r.rmse_high))
        .collect();
    let noise_time: Vec<BandPoint> = report
        .rows
        .iter()
        .map(|r| band(r.seconds, r.noise, r.noise, r.noise))
        .collect();
    let sampling = if report.stratified {
        "stratified"
    } else {
        "independent"
    };
    ErrorChart {
        title: format!(
            "{}: error against time ({}x{}, {} threads)",
            report.scene, report.width, report.height, report.threads
        ),
        x_label: "wall-clock seconds, parse + render (POV-Ray: its own statistics)".into(),
        y_label: "RMSE against the POV-Ray reference".into(),
        curves: vec![
            Curve {
                label: format!("penumbra RMSE ({sampling}; median, range of seeds)"),
                points: rmse_time,
                colour: 0,
                secondary: false,
            },
            Curve {
                label: "penumbra noise sqrt(V)".into(),
                points: noise_time,
                colour: 2,
                secondary: true,
            },
        ],
        markers: report
            .povray
            .iter()
            .map(|p| Marker {
                label: p.setting.clone(),
                x: p.net_seconds,
                y: p.rmse,
            })
            .collect(),
        floors,
        slopes: vec![-0.5, -1.0],
        targets: DEFAULT_TARGETS.to_vec(),
    }
}

/// `error_vs_spp`: RMSE, noise and bias against samples per pixel.
fn spp_chart(report: &ConvergeReport, floors: Vec<(String, f64)>) -> ErrorChart {
    let by_spp = |f: &dyn Fn(&PenumbraRow) -> (f64, f64, f64)| -> Vec<BandPoint> {
        report
            .rows
            .iter()
            .map(|r| {
                let (y, low, high) = f(r);
                band(r.spp, y, low, high)
            })
            .collect()
    };
    ErrorChart {
        title: format!("{}: error against samples per pixel", report.scene),
        x_label: "samples per pixel".into(),
        y_label: "error against the POV-Ray reference".into(),
        curves: vec![
            Curve {
                label: "RMSE (median, range of seeds)".into(),
                points: by_spp(&|r| (r.rmse, r.rmse_low, r.rmse_high)),
                colour: 0,
                secondary: false,
            },
            Curve {
                label: "noise sqrt(V)".into(),
                points: by_spp(&|r| (r.noise, r.noise, r.noise)),
                colour: 2,
                secondary: false,
            },
            Curve {
                label: "bias sqrt(B) (4x4 blocks)".into(),
                points: by_spp(&|r| (r.bias, r.bias, r.bias)),
                colour: 4,
                secondary: true,
            },
        ],
        markers: Vec::new(),
        floors,
        slopes: vec![-0.5, -1.0],
        targets: Vec::new(),
    }
}

/// The per-scene section body: the rows, POV-Ray's points, and the time-to-target table.
pub fn summary_markdown(report: &ConvergeReport) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{}x{}, {} threads, {} sampling; noise slope against spp {}; \
         penumbra's bias against POV-Ray sqrt(B) = {:.4} at {} spp \
         (per-pixel floor {:.4}).\n",
        report.width,
        report.height,
        report.threads,
        if report.stratified {
            "stratified"
        } else {
            "independent"
        },
        report.noise_slope.map_or("-".into(), |v| format!("{v:.2}")),
        report.bias_floor().unwrap_or(f64::NAN),
        report.rows.last().map_or(0.0, |r| r.spp),
        report.rows.last().map_or(f64::NAN, |r| r.pixel_floor),
    );
    let _ = writeln!(
        s,
        "| spp | seconds | RMSE (median) | noise sqrt(V) | bias sqrt(B) | tile failures |"
    );
    let _ = writeln!(s, "| ---: | ---: | ---: | ---: | ---: | ---: |");
    for r in &report.rows {
        let _ = writeln!(
            s,
            "| {} | {} | {:.5} | {:.5} | {:.5} | {}/{} |",
            r.spp,
            seconds3(r.seconds),
            r.rmse,
            r.noise,
            r.bias,
            r.tiles_failed,
            r.tiles_tested
        );
    }
    if !report.povray.is_empty() {
        let _ = writeln!(
            s,
            "\n| POV-Ray setting | seconds (parse + render) | seconds (process) | RMSE |"
        );
        let _ = writeln!(s, "| --- | ---: | ---: | ---: |");
        for p in &report.povray {
            let _ = writeln!(
                s,
                "| `{}` | {} | {} | {:.5} |",
                p.setting,
                seconds3(p.net_seconds),
                seconds3(p.seconds),
                p.rmse
            );
        }
    }
    let _ = writeln!(
        s,
        "\n| target RMSE | penumbra | POV-Ray | speed-up |\n| ---: | ---: | ---: | ---: |"
    );
    let pov_max = report
        .povray
        .iter()
        .map(|p| p.net_seconds)
        .fold(0.0, f64::max);
    for t in &report.targets {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} |",
            t.target,
            t.penumbra,
            t.povray.map_or("-".into(), |r| r.to_string()),
            t.speed_up_text(pov_max)
        );
    }
    s
}

/// Cells "| penumbra | POV-Ray | speed-up |" per target, for the table over all scenes.
pub fn speed_up_cells(report: &ConvergeReport) -> String {
    let pov_max = report
        .povray
        .iter()
        .map(|p| p.net_seconds)
        .fold(0.0, f64::max);
    let mut s = String::new();
    for t in &report.targets {
        let _ = write!(
            s,
            " {} | {} | {} |",
            t.penumbra,
            t.povray.map_or("-".into(), |r| r.to_string()),
            t.speed_up_text(pov_max)
        );
    }
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_to_reach_interpolates_in_log_log() {
        // error = t^-1/2: 0.1 at t = 100, 0.01 at 10^4; 0.02 lies at t = 2500 exactly.
        let points = [(100.0, 0.1), (1e4, 0.01)];
        let Reach::At(t) = time_to_reach(&points, 0.02) else {
            panic!("not reached")
        };
        assert!((t - 2500.0).abs() < 1e-6, "{t}");
        assert_eq!(time_to_reach(&points, 0.2), Reach::AtMost(100.0));
        assert_eq!(
            time_to_reach(&points, 0.001),
            Reach::NotReached { best: 0.01 }
        );
    }

    #[test]
    fn time_to_reach_ignores_slower_worse_points() {
        // The point at t = 50 is worse than the one at t = 10: the envelope skips it.
        let points = [(10.0, 0.05), (50.0, 0.08), (1000.0, 0.005)];
        let Reach::At(t) = time_to_reach(&points, 0.01) else {
            panic!("not reached")
        };
        let expected = (10f64.ln() + (0.2f64.ln() / 0.1f64.ln()) * 100f64.ln()).exp();
        assert!((t - expected).abs() < 1e-9 * expected, "{t} vs {expected}");
    }

    #[test]
    fn slope_of_a_power_law() {
        let points: Vec<(f64, f64)> = [1.0, 4.0, 16.0, 64.0]
            .iter()
            .map(|&n: &f64| (n, 0.3 * n.powf(-0.75)))
            .collect();
        let slope = log_log_slope(&points).expect("slope");
        assert!((slope + 0.75).abs() < 1e-12, "{slope}");
        assert_eq!(log_log_slope(&[(1.0, 1.0)]), None);
    }

    /// Sample counts run from 1 to 2^20, and fractional ones are adaptive averages.
    #[test]
    fn sample_counts_are_checked() {
        let request = |spp: Vec<f64>, adaptive: bool| ConvergeRequest {
            scene: PathBuf::from("s.pov"),
            declares: Vec::new(),
            include_paths: Vec::new(),
            reference: PathBuf::from("r.exr"),
            spp,
            seeds: 2,
            povray: false,
            output_dir: PathBuf::from("out"),
            threads: None,
            stratified: true,
            targets: vec![0.01],
            light_samples: LightSamples::Cover,
            adaptive,
        };
        let invalid =
            |r: ConvergeRequest| matches!(validate(&r), Err(StudyError::InvalidRequest(_)));
        assert!(validate(&request(vec![1.0, 1.5, 2.0], true)).is_ok());
        assert!(invalid(request(vec![1.0, 1.5], false)));
        assert!(invalid(request(vec![0.5], true)));
        assert!(invalid(request(Vec::new(), true)));
        assert!(validate(&request(vec![1.0, 4.0], false)).is_ok());
    }

    #[test]
    fn median_of_even_and_odd_counts() {
        assert_eq!(median_range(&[3.0, 1.0, 2.0]), (2.0, 1.0, 3.0));
        assert_eq!(median_range(&[4.0, 1.0, 2.0, 3.0]), (2.5, 1.0, 4.0));
    }
}
