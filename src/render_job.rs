//! Runs a [`Job`]: every frame is parsed with its own clock, the render-ready scene is
//! rebuilt only when the frame's scene differs from the last one, and each frame is written
//! under its own name (a window full-size with the rest black, as POV-Ray writes it, or
//! cropped).

use std::collections::hash_map::DefaultHasher;
use std::hash::Hasher;
use std::path::PathBuf;

use crate::lang::{Diagnostic, LoadOptions, load_scene_with};
use crate::output::{BitDepth, Image, write_image};
use crate::povray_args::Job;
use crate::render::{PreparedScene, Progress, RenderOptions, RenderStats};

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
    let options = RenderOptions {
        width: job.width as usize,
        height: job.height as usize,
        samples_per_pixel: job.sampling.spp,
        adaptive: job.sampling.adaptive,
        seed: job.seed,
        threads: job.threads,
        window: job.window.clone(),
        quality: job.quality,
        ..settings.base.clone()
    };
    let mut include_paths = job.library_paths.clone();
    if let Some(dir) = job.scene.parent().filter(|d| !d.as_os_str().is_empty()) {
        include_paths.push(dir.to_path_buf());
    }
    let mut prepared: Option<(u64, PreparedScene)> = None;
    let mut reports = Vec::new();
    for (index, frame) in job.frames.iter().enumerate() {
        progress.frame(index, job.frames.len(), &frame.output);
        let load = LoadOptions {
            declares: job.declares.clone(),
            include_paths: include_paths.clone(),
            image_width: job.width,
            image_height: job.height,
            clock: frame.clock,
        };
        let loaded = load_scene_with(&job.scene, &load, settings.skip_unsupported)
            .map_err(|d| d.to_string())?;
        progress.warnings(&loaded.warnings);
        let key = scene_hash(&loaded.scene);
        let rebuilt = prepared.as_ref().is_none_or(|(k, _)| *k != key);
        if rebuilt {
            prepared = Some((key, PreparedScene::new(&loaded.scene)));
        }
        let (_, scene) = prepared.as_ref().expect("prepared above");
        let (film, stats) = crate::render::render(scene, &options, &SampleProgress(progress))
            .map_err(|e| e.to_string())?;
        let mut image = crate::film_image(&film);
        if job.crop
            && let Some(w) = &job.window
        {
            image = crop(&image, w);
        }
        if job.write {
            let depth = if job.sixteen_bits {
                BitDepth::Sixteen
            } else {
                BitDepth::Eight
            };
            if let Some(dir) = frame.output.parent().filter(|d| !d.as_os_str().is_empty()) {
                std::fs::create_dir_all(dir)
                    .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
            }
            write_image(&frame.output, &image, depth).map_err(|e| e.to_string())?;
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
