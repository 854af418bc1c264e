//! Runs a [`Job`]: every frame is parsed with its own clock, the render-ready scene is
//! rebuilt only when the frame's scene differs from the last one, and each frame is written
//! under its own name (a window full-size with the rest black, as POV-Ray writes it, or
//! cropped).

use std::path::PathBuf;

use crate::lang::{AnimationClock, Diagnostic, LoadOptions, load_scene_with};
use crate::output::{BitDepth, Image, ShardHeader, read_shard, write_image, write_shard};
use crate::povray_args::{Frame, Job};
use crate::render::{Film, PreparedScene, Progress, RenderOptions, RenderStats};

/// What a job reports as it goes, from worker threads.
pub trait JobProgress: Sync {
    /// Frame `index` of `count` (from 0) is about to be parsed.
    fn frame(&self, index: usize, count: usize, output: &std::path::Path);
    /// Its render's progress.
    fn samples(&self, done: u64, total: u64);
    /// Warnings from reading the scene.
    fn warnings(&self, warnings: &[Diagnostic]);
    /// The scene's `#debug` text, which POV-Ray prints as it parses (once per frame).
    fn debug(&self, _text: &str) {}
    /// True once the user asked to stop (Ctrl-C, SIGTERM).
    fn cancelled(&self) -> bool {
        false
    }
}

/// One written frame.
#[derive(Clone, Debug)]
pub struct FrameReport {
    pub output: PathBuf,
    pub width: usize,
    pub height: usize,
    pub stats: RenderStats,
    /// Whether the render-ready scene was rebuilt for this frame.
    pub rebuilt: bool,
}

/// Options for [`run_job`] beyond the job itself.
#[derive(Clone, Debug, Default)]
pub struct JobSettings {
    /// The render options every frame starts from (size, samples, window, seed and quality
    /// are the job's).
    pub base: RenderOptions,
    pub skip_unsupported: bool,
    /// The evaluator's memory budget (`--max-memory`); `None`: the default.
    pub max_memory: Option<u64>,
    /// `--allow-write DIR` for `#fopen ... write`.
    pub allow_write: Option<PathBuf>,
    /// Write each frame's film as a shard file (sums, for `penumbra merge`), not an image.
    pub shards: bool,
    /// Continue from each frame's checkpoint; frames already written are skipped.
    pub resume: bool,
    /// Rewrite this PNG with the image so far at most this often.
    pub preview: Option<(PathBuf, std::time::Duration)>,
}

/// Why a job stopped.
#[derive(Debug)]
pub enum JobError {
    Failed(String),
    /// Cancelled: the frame's samples so far are in `checkpoint`.
    Interrupted {
        checkpoint: PathBuf,
        done: u64,
        total: u64,
    },
}

impl std::fmt::Display for JobError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            JobError::Failed(m) => f.write_str(m),
            JobError::Interrupted {
                checkpoint,
                done,
                total,
            } => write!(
                f,
                "interrupted after {done} of {total} samples; they are saved in {}",
                checkpoint.display()
            ),
        }
    }
}

impl From<String> for JobError {
    fn from(m: String) -> Self {
        JobError::Failed(m)
    }
}

/// Where an output's checkpoint goes: beside it.
pub fn checkpoint_path(output: &std::path::Path) -> PathBuf {
    let mut name = output.as_os_str().to_owned();
    name.push(".checkpoint");
    PathBuf::from(name)
}

impl JobProgress for () {
    fn frame(&self, _: usize, _: usize, _: &std::path::Path) {}
    fn samples(&self, _: u64, _: u64) {}
    fn warnings(&self, _: &[Diagnostic]) {}
}

/// A job's progress as a render sees it, with the preview it rewrites between passes.
struct SampleProgress<'a> {
    job: &'a dyn JobProgress,
    preview: Option<&'a (PathBuf, std::time::Duration)>,
    last_preview: std::sync::Mutex<std::time::Instant>,
}

impl Progress for SampleProgress<'_> {
    fn advance(&self, done: u64, total: u64) {
        self.job.samples(done, total);
    }

    fn cancelled(&self) -> bool {
        self.job.cancelled()
    }

    fn pass(&self, film: &Film) {
        let Some((path, every)) = self.preview else {
            return;
        };
        let mut last = self.last_preview.lock().unwrap_or_else(|e| e.into_inner());
        if last.elapsed() >= *every {
            // A preview that cannot be written must not stop the render.
            let _ = write_image(path, &crate::film_image(film), BitDepth::Eight);
            *last = std::time::Instant::now();
        }
    }
}

/// Renders every frame of `job` and writes it (unless the job does not write): as an
/// image, or with `settings.shards` as a shard. Cancelled, the frame's film so far is saved
/// as a checkpoint beside its output, from which `settings.resume` continues.
pub fn run_job(
    job: &Job,
    settings: &JobSettings,
    progress: &dyn JobProgress,
) -> Result<Vec<FrameReport>, JobError> {
    let mut frames = FrameRenderer {
        job,
        settings,
        options: job_options(job, settings),
        include_paths: include_paths(job),
        prepared: None,
        progress,
    };
    let mut reports = Vec::new();
    for (index, frame) in job.frames.iter().enumerate() {
        let checkpoint = checkpoint_path(&frame.output);
        if settings.resume && !checkpoint.exists() && frame.output.exists() {
            // Outputs are written atomically: one that exists is complete.
            continue;
        }
        progress.frame(index, job.frames.len(), &frame.output);
        let (film, stats, rebuilt) = frames.render(frame)?;
        if !stats.complete {
            return Err(frames.save_checkpoint(frame, &film, &checkpoint)?);
        }
        let (width, height) = frames.write(frame, &film)?;
        if settings.resume && checkpoint.exists() {
            std::fs::remove_file(&checkpoint)
                .map_err(|e| format!("cannot remove {}: {e}", checkpoint.display()))?;
        }
        reports.push(FrameReport {
            output: frame.output.clone(),
            width,
            height,
            stats,
            rebuilt,
        });
    }
    Ok(reports)
}

/// One frame's film, unwritten (default settings).
pub fn render_frame_film(
    job: &Job,
    frame: &Frame,
    progress: &dyn JobProgress,
) -> Result<Film, String> {
    let settings = JobSettings::default();
    let mut renderer = FrameRenderer {
        job,
        settings: &settings,
        options: job_options(job, &settings),
        include_paths: include_paths(job),
        prepared: None,
        progress,
    };
    renderer.render(frame).map(|(film, _, _)| film)
}

/// The render options of a job's frames.
fn job_options(job: &Job, settings: &JobSettings) -> RenderOptions {
    RenderOptions {
        width: job.width as usize,
        height: job.height as usize,
        samples_per_pixel: job.sampling.spp,
        average_spp: job.sampling.average,
        adaptive: job.sampling.adaptive,
        seed: job.seed,
        threads: job.threads,
        window: job.window.clone(),
        quality: job.quality,
        ..settings.base.clone()
    }
}

/// The library path, then the scene's folder.
fn include_paths(job: &Job) -> Vec<PathBuf> {
    let mut paths = job.library_paths.clone();
    if let Some(dir) = job.scene.parent().filter(|d| !d.as_os_str().is_empty()) {
        paths.push(dir.to_path_buf());
    }
    paths
}

/// What renders the frames: the last render-ready scene is kept with its scene's hash.
struct FrameRenderer<'a> {
    job: &'a Job,
    settings: &'a JobSettings,
    options: RenderOptions,
    include_paths: Vec<PathBuf>,
    prepared: Option<(u64, PreparedScene)>,
    progress: &'a dyn JobProgress,
}

impl FrameRenderer<'_> {
    /// A frame's film; with motion blur, the shutter (the frame's clock to the next
    /// frame's) is split into `motion_blur` equal times, each parsed at its middle and
    /// rendered with its own share of the sample indices, so the merged film is one render
    /// whose samples are spread over the shutter.
    fn render(&mut self, frame: &Frame) -> Result<(Film, RenderStats, bool), String> {
        let n = self.job.motion_blur.max(1);
        if n == 1 || frame.clock.clock_delta == 0.0 {
            let rebuilt = self.prepare(frame.clock)?;
            let checkpoint = self.checkpoint(frame)?;
            let (film, stats) = self.run(&self.options, checkpoint.as_ref())?;
            return Ok((film, stats, rebuilt));
        }
        if self.settings.resume {
            return Err("--resume does not work with --motion-blur".into());
        }
        let spp = self.options.samples_per_pixel;
        if self.options.adaptive || spp < n {
            return Err(format!(
                "--motion-blur {n} needs at least {n} samples per pixel and no adaptive sampling"
            ));
        }
        let mut film = Film::new(self.options.width, self.options.height);
        let mut total: Option<RenderStats> = None;
        let mut rebuilt = false;
        for k in 0..n {
            let mut clock = frame.clock;
            clock.clock += clock.clock_delta * (f64::from(k) + 0.5) / f64::from(n);
            rebuilt |= self.prepare(clock)?;
            let options = RenderOptions {
                sample_range: Some(k * spp / n..(k + 1) * spp / n),
                ..self.options.clone()
            };
            let (part, stats) = self.run(&options, None)?;
            if !stats.complete {
                return Err("interrupted (a motion-blurred frame keeps no checkpoint)".into());
            }
            film.merge(&part);
            total = Some(match total {
                None => stats,
                Some(mut t) => {
                    t.wall += stats.wall;
                    t.samples += stats.samples;
                    t.rays.add(&stats.rays);
                    t
                }
            });
        }
        Ok((film, total.expect("at least one time"), rebuilt))
    }

    /// Parses the scene at `clock`; rebuilds the render-ready scene if it changed.
    fn prepare(&mut self, clock: AnimationClock) -> Result<bool, String> {
        let load = LoadOptions {
            declares: self.job.declares.clone(),
            include_paths: self.include_paths.clone(),
            image_width: self.job.width,
            image_height: self.job.height,
            clock,
            max_memory: self.settings.max_memory,
            allow_write: self.settings.allow_write.clone(),
        };
        let loaded = load_scene_with(&self.job.scene, &load, self.settings.skip_unsupported)
            .map_err(|d| d.to_string())?;
        self.progress.warnings(&loaded.warnings);
        if !loaded.debug.is_empty() {
            self.progress.debug(&loaded.debug);
        }
        let key = loaded.inputs_hash;
        let rebuilt = self.prepared.as_ref().is_none_or(|(k, _)| *k != key);
        if rebuilt {
            self.prepared = Some((key, PreparedScene::new(&loaded.scene)));
        }
        Ok(rebuilt)
    }

    fn run(
        &self,
        options: &RenderOptions,
        checkpoint: Option<&Film>,
    ) -> Result<(Film, RenderStats), String> {
        let (_, scene) = self.prepared.as_ref().expect("prepared first");
        let progress = SampleProgress {
            job: self.progress,
            preview: self.settings.preview.as_ref(),
            last_preview: std::sync::Mutex::new(std::time::Instant::now()),
        };
        crate::render::render_from(scene, options, checkpoint, &progress).map_err(|e| e.to_string())
    }

    /// What the frame's shard or checkpoint says about its render.
    fn header(&self, frame: &Frame, complete: bool) -> ShardHeader {
        let o = &self.options;
        let spp = o.samples_per_pixel.max(1);
        ShardHeader {
            version: env!("CARGO_PKG_VERSION").to_string(),
            scene_hash: self.prepared.as_ref().map_or(0, |(k, _)| *k),
            scene: self.job.scene.display().to_string(),
            frame: frame.number,
            width: o.width,
            height: o.height,
            spp,
            seed: o.seed,
            options: format!(
                "quality {} area-lights {:?} splitting {:?} light-samples {:?} roulette {} stratified {} window {:?} adaptive {} average-spp {:?} motion-blur {}",
                o.quality,
                o.area_lights,
                o.splitting,
                o.light_samples,
                o.roulette,
                o.stratified,
                o.window,
                o.adaptive,
                o.average_spp,
                self.job.motion_blur
            ),
            range: o.sample_range.clone().unwrap_or(0..spp),
            complete,
        }
    }

    /// With `resume`, the frame's checkpoint if it has one, checked against this render.
    fn checkpoint(&self, frame: &Frame) -> Result<Option<Film>, String> {
        let path = checkpoint_path(&frame.output);
        if !self.settings.resume || !path.exists() {
            return Ok(None);
        }
        let shard = read_shard(&path).map_err(|e| e.to_string())?;
        let mut want = self.header(frame, false);
        want.scene = shard.header.scene.clone();
        if shard.header != want {
            return Err(format!(
                "{} is the checkpoint of another render (another scene, size, seed or options); remove it to start again",
                path.display()
            ));
        }
        Ok(Some(shard.film))
    }

    fn save_checkpoint(
        &self,
        frame: &Frame,
        film: &Film,
        path: &std::path::Path,
    ) -> Result<JobError, String> {
        write_shard(path, &self.header(frame, false), film).map_err(|e| e.to_string())?;
        let range = self.header(frame, false).range;
        let window = self.options.window.as_ref();
        let pixels = window.map_or(film.pixels.len(), |w| w.x.len() * w.y.len()) as u64;
        Ok(JobError::Interrupted {
            checkpoint: path.to_path_buf(),
            done: film.samples(),
            total: pixels * u64::from(range.end - range.start),
        })
    }

    /// Writes the frame as a shard or an image: the written size.
    fn write(&self, frame: &Frame, film: &Film) -> Result<(usize, usize), String> {
        if self.settings.shards {
            if self.job.write {
                write_shard(&frame.output, &self.header(frame, true), film)
                    .map_err(|e| e.to_string())?;
            }
            return Ok((film.width, film.height));
        }
        let mut image = crate::film_image(film);
        if self.job.crop
            && let Some(w) = &self.job.window
        {
            image = crop(&image, w);
        }
        if self.job.write {
            write_frame(self.job, &frame.output, &image)?;
        }
        Ok((image.width, image.height))
    }
}

fn write_frame(job: &Job, output: &std::path::Path, image: &Image) -> Result<(), String> {
    let depth = if job.sixteen_bits {
        BitDepth::Sixteen
    } else {
        BitDepth::Eight
    };
    if let Some(dir) = output.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    }
    write_image(output, image, depth).map_err(|e| e.to_string())
}

/// The window's pixels as an image of its own size.
pub fn crop(image: &Image, window: &crate::render::PixelWindow) -> Image {
    let mut pixels = Vec::with_capacity(window.x.len() * window.y.len());
    for y in window.y.clone() {
        let row = y * image.width;
        pixels.extend_from_slice(&image.pixels[row + window.x.start..row + window.x.end]);
    }
    Image {
        width: window.x.len(),
        height: window.y.len(),
        pixels,
    }
}
