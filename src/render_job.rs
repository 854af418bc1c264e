//! Runs a [`Job`]: every frame is parsed with its own clock, the render-ready scene is
//! rebuilt only when the frame's scene differs from the last one, and each frame is written
//! under its own name (a window full-size with the rest black, as POV-Ray writes it, or
//! cropped).

use std::collections::hash_map::DefaultHasher;
use std::hash::Hasher;
use std::path::PathBuf;

use crate::lang::{AnimationClock, Diagnostic, LoadOptions, load_scene_with};
use crate::output::{BitDepth, Image, write_image};
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
}

impl JobProgress for () {
    fn frame(&self, _: usize, _: usize, _: &std::path::Path) {}
    fn samples(&self, _: u64, _: u64) {}
    fn warnings(&self, _: &[Diagnostic]) {}
}

struct SampleProgress<'a>(&'a dyn JobProgress);

impl Progress for SampleProgress<'_> {
    fn advance(&self, done: u64, total: u64) {
        self.0.samples(done, total);
    }
}

/// Renders every frame of `job` and writes it (unless the job does not write).
pub fn run_job(
    job: &Job,
    settings: &JobSettings,
    progress: &dyn JobProgress,
) -> Result<Vec<FrameReport>, String> {
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
        progress.frame(index, job.frames.len(), &frame.output);
        let (film, stats, rebuilt) = frames.render(frame)?;
        let mut image = crate::film_image(&film);
        if job.crop
            && let Some(w) = &job.window
        {
            image = crop(&image, w);
        }
        if job.write {
            write_frame(job, &frame.output, &image)?;
        }
        reports.push(FrameReport {
            output: frame.output.clone(),
            width: image.width,
            height: image.height,
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
            let (film, stats) = self.run(&self.options)?;
            return Ok((film, stats, rebuilt));
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
            let (part, stats) = self.run(&options)?;
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
        let key = scene_hash(&loaded.scene);
        let rebuilt = self.prepared.as_ref().is_none_or(|(k, _)| *k != key);
        if rebuilt {
            self.prepared = Some((key, PreparedScene::new(&loaded.scene)));
        }
        Ok(rebuilt)
    }

    fn run(&self, options: &RenderOptions) -> Result<(Film, RenderStats), String> {
        let (_, scene) = self.prepared.as_ref().expect("prepared first");
        crate::render::render(scene, options, &SampleProgress(self.progress))
            .map_err(|e| e.to_string())
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

/// A hash of everything the scene holds (through its Debug form, without building the
/// text), so frames whose scene did not change keep their render-ready scene.
fn scene_hash(scene: &crate::scene::Scene) -> u64 {
    struct HashWriter(DefaultHasher);
    impl std::fmt::Write for HashWriter {
        fn write_str(&mut self, s: &str) -> std::fmt::Result {
            self.0.write(s.as_bytes());
            Ok(())
        }
    }
    let mut w = HashWriter(DefaultHasher::new());
    let _ = std::fmt::write(&mut w, format_args!("{scene:?}"));
    w.0.finish()
}
