//! Rendering: the sampler, the integrator, lights, the film, and the one loop that owns
//! tiles, threads and progress.

pub mod camera;
mod corners;
pub mod dimensions;
pub mod film;
pub mod fog;
pub mod integrator;
pub mod lights;
pub mod media;
pub mod mesh_camera;
pub mod photons;
pub mod prepared;
pub mod rainbow;
pub mod sampler;
pub mod target;

use std::ops::Range;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use glam::DVec3;
use rayon::prelude::*;

pub use film::{Film, PixelSum};
pub use integrator::{Integrator, RayCounts, Splitting};
pub use lights::{AreaLightMode, LightSamples};
pub use prepared::PreparedScene;
pub use sampler::PixelSampler;

use crate::geometry::Ray;
pub use camera::camera_ray;
use dimensions::Purpose;

const TILE: usize = 16;

/// Whether a render of `spp` samples per pixel spreads them adaptively unless told
/// otherwise. Measured at 640x480 on the twelve scenes of docs/convergence.md (2 seeds, one
/// thread; squared error times time, uniform over adaptive): from 2 spp on, adaptive is the
/// more efficient on every scene (1.09x to 54x); at 1 spp it is the less efficient on 8 of
/// the 12 (0.80x to 0.92x), its pilot then being the whole budget. (A fractional average
/// above 1, which rounds up to 2, is adaptive: at 1.125 it beat uniform at 1 on 11 of 12.)
pub fn adaptive_by_default(spp: u32) -> bool {
    spp >= 2
}

/// The sample counts `--spp` accepts, whole or (adaptive) fractional: from 1 to 2^20.
pub fn spp_in_range(spp: f64) -> bool {
    (1.0..=f64::from(1u32 << 20)).contains(&spp)
}

#[derive(Clone, Debug)]
pub struct RenderOptions {
    pub width: usize,
    pub height: usize,
    pub samples_per_pixel: u32,
    pub seed: u64,
    /// Which sample indices to render (default: all). Renders of disjoint ranges of the same
    /// scene, size, sample count and seed sum to exactly the full render.
    pub sample_range: Option<Range<u32>>,
    /// Worker threads; `None` lets rayon choose.
    pub threads: Option<usize>,
    pub roulette: bool,
    pub area_lights: AreaLightMode,
    pub splitting: Splitting,
    /// Shadow rays per area light per shading point.
    pub light_samples: LightSamples,
    /// Spend the samples where a pilot pass finds the most noise (same average count).
    pub adaptive: bool,
    /// Stratified jittered samples (the default); false draws independent uniform samples,
    /// for convergence studies that need the N^-1/2 baseline.
    pub stratified: bool,
    /// Render only these pixels (POV-Ray's `+SR +ER +SC +EC`); the others stay black. Each
    /// pixel's samples depend only on the pixel, sample index and seed, so the window holds
    /// exactly the full render's pixels.
    pub window: Option<PixelWindow>,
    /// POV-Ray's `+Q` quality level (0-11, default 9): below 8 no reflection or refraction,
    /// below 5 area lights as point lights, below 4 no shadows, below 2 no diffuse or
    /// highlights (the pigment colour only).
    pub quality: u32,
    /// Render in passes of doubling sample counts, each reported to [`Progress::pass`]
    /// (for previews); the film is the same as in one pass.
    pub passes: bool,
    /// Render in passes until the estimated noise is below this (see [`target`]).
    pub target_error: Option<target::TargetError>,
    /// An adaptive render's average samples per pixel where it is not whole, above 1
    /// (`--spp 1.5`): `samples_per_pixel` is then its ceiling, which sizes the pilot's
    /// shadow rays and the sample ranges of shards. Between one sample per pixel and two,
    /// where each whole step doubles the time, the first extra samples go to the pixels
    /// that change most (docs/convergence.md).
    pub average_spp: Option<f64>,
    /// Let an adaptive render take its pilot at the pixels' corners where it may (the
    /// default; src/render/corners.rs). False keeps the pilot of one sample per pixel
    /// everywhere: to compare the two, and to test that pilot.
    pub corner_pilot: bool,
}

/// A rectangle of pixels: columns `x`, rows `y` (row 0 at the top).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PixelWindow {
    pub x: Range<usize>,
    pub y: Range<usize>,
}

impl PixelWindow {
    pub fn contains(&self, x: usize, y: usize) -> bool {
        self.x.contains(&x) && self.y.contains(&y)
    }
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 320,
            height: 240,
            samples_per_pixel: 16,
            seed: 0,
            sample_range: None,
            threads: None,
            roulette: true,
            area_lights: AreaLightMode::Pov,
            splitting: Splitting::Both,
            light_samples: LightSamples::Cover,
            adaptive: false,
            stratified: true,
            window: None,
            quality: 9,
            passes: false,
            target_error: None,
            average_spp: None,
            corner_pilot: true,
        }
    }
}

#[derive(Clone, Debug)]
pub struct RenderStats {
    pub wall: Duration,
    pub samples: u64,
    pub rays: RayCounts,
    /// What the render noticed about the scene, as POV-Ray's shutdown warnings do (an
    /// isosurface steeper than its max_gradient).
    pub notes: Vec<String>,
    /// False when the render was cancelled before it took all its samples.
    pub complete: bool,
}

impl RenderStats {
    pub fn rays_per_second(&self) -> f64 {
        self.rays.total() as f64 / self.wall.as_secs_f64().max(1e-9)
    }
}

/// Reports progress as a fraction done, and says when to stop; called from worker threads.
pub trait Progress: Sync {
    fn advance(&self, done: u64, total: u64);
    /// True once the render should stop (Ctrl-C): it ends at the next sample boundary and
    /// returns the film so far, whose per-pixel counts say which samples it holds.
    fn cancelled(&self) -> bool {
        false
    }
    /// A pass of a render in passes (preview, target error) has ended: the film so far.
    fn pass(&self, _film: &Film) {}
}

impl Progress for () {
    fn advance(&self, _: u64, _: u64) {}
}

#[derive(Debug)]
pub struct RenderError(pub String);

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for RenderError {}

/// Renders into a film. Each pixel's samples are taken in index order by one thread, and
/// tiles are written back in a fixed order, so the result is the same for any thread count.
/// With `adaptive`, a pilot pass measures the noise and the rest of the sample budget
/// follows it (see [`adaptive_passes`]); with a target error, passes continue until the
/// noise estimate is below it (see [`target`]).
pub fn render(
    scene: &PreparedScene,
    options: &RenderOptions,
    progress: &dyn Progress,
) -> Result<(Film, RenderStats), RenderError> {
    render_from(scene, options, None, progress)
}

/// Continues a render from a checkpoint: the film of an interrupted render of the same
/// scene and options, whose pixel counts say how many of each pixel's samples it holds. The
/// result is the uninterrupted render's film exactly.
pub fn render_from(
    scene: &PreparedScene,
    options: &RenderOptions,
    checkpoint: Option<&Film>,
    progress: &dyn Progress,
) -> Result<(Film, RenderStats), RenderError> {
    let start = Instant::now();
    let range = sample_range(options)?;
    if let Some(done) = checkpoint {
        check_checkpoint(options, done)?;
    }
    let pool = match options.threads {
        Some(n) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(n.max(1))
                .build()
                .map_err(|e| RenderError(format!("cannot start {n} threads: {e}")))?,
        ),
        None => None,
    };
    let run = |plan: &SamplePlan, progress: &dyn Progress, film: Option<Film>| {
        render_pass(scene, options, plan, progress, film)
    };
    // Everything in the pool, the passes and the work between them (the adaptive pilot's
    // analysis, the film's first touch), so that all of it takes the threads asked for.
    let passes = || {
        if let Some(target) = &options.target_error {
            target::render_to_error(options, target, &run, progress)
        } else if options.adaptive {
            adaptive_passes(
                options,
                AdaptiveScene::of(scene, options),
                Share {
                    range: range.clone(),
                    spp: options.samples_per_pixel.max(1),
                },
                checkpoint,
                &run,
                progress,
            )
        } else {
            uniform_passes(options, range.clone(), checkpoint, &run, progress)
        }
    };
    let (film, rays, samples) = match &pool {
        Some(pool) => pool.install(passes),
        None => passes(),
    };
    let complete = match (&options.target_error, options.adaptive) {
        (None, false) => holds_range(options, &film, range.len() as u32),
        _ => !progress.cancelled(),
    };
    let stats = RenderStats {
        wall: start.elapsed(),
        samples,
        rays,
        notes: scene.world.gradient_notes(),
        complete,
    };
    Ok((film, stats))
}

/// The sample indices the options ask for, checked.
fn sample_range(options: &RenderOptions) -> Result<Range<u32>, RenderError> {
    let (w, h) = (options.width, options.height);
    if w == 0 || h == 0 {
        return Err(RenderError("the image size must be at least 1x1".into()));
    }
    let spp = options.samples_per_pixel.max(1);
    let range = options.sample_range.clone().unwrap_or(0..spp);
    if range.end > spp || range.start > range.end {
        return Err(RenderError(format!(
            "sample range {}..{} is outside 0..{spp}",
            range.start, range.end
        )));
    }
    if options.target_error.is_some() && options.sample_range.is_some() {
        return Err(RenderError(
            "--target-error cannot be split into sample ranges".into(),
        ));
    }
    if let Some(average) = options.average_spp {
        check_average(average, spp, options.adaptive)?;
    }
    Ok(range)
}

/// A fractional average is for adaptive renders, whose counts differ per pixel anyway, and
/// lies in (spp - 1, spp], above one sample (every pixel takes the pilot's).
fn check_average(average: f64, spp: u32, adaptive: bool) -> Result<(), RenderError> {
    if !adaptive {
        return Err(RenderError(format!(
            "{average} samples per pixel on average needs adaptive sampling (uniform renders take whole samples)"
        )));
    }
    if !(average > 1.0 && average <= f64::from(spp) && average > f64::from(spp) - 1.0) {
        return Err(RenderError(format!(
            "an average of {average} samples per pixel must be above 1 and round up to {spp}"
        )));
    }
    Ok(())
}

fn check_checkpoint(options: &RenderOptions, done: &Film) -> Result<(), RenderError> {
    if options.target_error.is_some() {
        return Err(RenderError(
            "target-error renders cannot resume from a checkpoint".into(),
        ));
    }
    if (done.width, done.height) != (options.width, options.height) {
        return Err(RenderError(format!(
            "the checkpoint is {}x{}, the render {}x{}",
            done.width, done.height, options.width, options.height
        )));
    }
    Ok(())
}

/// Whether every pixel the render covers holds `n` samples.
fn holds_range(options: &RenderOptions, film: &Film, n: u32) -> bool {
    let w = options.width;
    film.pixels.iter().enumerate().all(|(i, p)| {
        let inside = options
            .window
            .as_ref()
            .is_none_or(|win| win.contains(i % w, i / w));
        !inside || p.count == n
    })
}

/// A uniform render: every pixel takes the samples of `range` (those after the
/// checkpoint's), in one pass, or with `options.passes` in passes of doubling size reported
/// to `progress` (each pixel still takes its samples in index order, so the film is the
/// same).
fn uniform_passes(
    options: &RenderOptions,
    range: Range<u32>,
    checkpoint: Option<&Film>,
    run: &Pass,
    progress: &dyn Progress,
) -> (Film, RayCounts, u64) {
    let passes = if options.passes {
        doubling(range.clone())
    } else {
        vec![range.clone()]
    };
    // Each pass adds its samples to the film (the checkpoint's, or the first pass's own).
    let mut film = checkpoint.cloned();
    let before = film.as_ref().map_or(0, Film::samples);
    let mut rays = RayCounts::default();
    for pass in passes {
        let plan = SamplePlan::Uniform {
            spp: options.samples_per_pixel.max(1),
            range: pass,
            first: range.start,
            checkpoint,
            seed: options.seed,
            position_seed: options.seed,
            fixed_light: None,
        };
        let PassOutput {
            film: part,
            rays: pass_rays,
            ..
        } = run(&plan, progress, film.take());
        let film = film.insert(part);
        rays.add(&pass_rays);
        if progress.cancelled() {
            break;
        }
        progress.pass(film);
    }
    let film = film.unwrap_or_else(|| Film::new(options.width, options.height));
    let samples = film.samples() - before;
    (film, rays, samples)
}

/// `range` cut into passes of 1, 1, 2, 4, ... samples.
fn doubling(range: Range<u32>) -> Vec<Range<u32>> {
    let mut passes = Vec::new();
    let mut at = range.start;
    while at < range.end {
        let size = (at - range.start).max(1);
        let end = (at + size).min(range.end);
        passes.push(at..end);
        at = end;
    }
    passes
}

/// Shadow rays per area light of each adaptive pilot sample of a render of `spp` samples
/// per pixel: spread over the light, so that a pixel whose light is partly hidden shows it
/// in its own rays more often than not. Four, up to eight from 8 spp on: more make the
/// pilot's values in a penumbra less noisy, so the change around each pixel says more of
/// where the error is, which repays their cost once the budget is large. Measured at
/// 640x480, adaptive, 3 seeds: squared error x time with 8 rays, lower than with 4 by,
/// at 4 / 8 / 16 / 32 spp: soft_shadow -2 / 17 / 21 / 14%, area_grid_6x2 -23 / -1 / 2 /
/// 11%, area_circular_9x9 12 / 30 / 27 / 25%, area_illumination -4 / -4 / 1 / 1%,
/// area_adaptive 1% (its adaptive rule sends the pilot's rays).
fn pilot_light_rays(spp: u32) -> u32 {
    spp.clamp(4, 8)
}

/// How far (in pixels) around a pixel the pilot looks for a penumbra. One pixel's few shadow
/// rays can all agree where a penumbra is all the same, only faint: at its fringe, where
/// little of the light is hidden. It is seldom that nothing within this reach shows it.
/// Measured at 640x480, adaptive, 3 seeds, RMSE against 3 pixels: at 4 spp soft_shadow
/// 0.00138 -> 0.00126 and the 9x9 light 0.00116 -> 0.00105 for the same time, at 2 spp
/// 2-4% lower, from 8 spp on the same (5 pixels: as 4).
const PENUMBRA_REACH: usize = 4;

/// A render pass, as `render` runs it on its thread pool.
/// A pass over the image: its plan, and the film it adds its samples to (a new one when
/// `None`); a pass that adds to the film it continues needs no film of its own.
type Pass<'a> = dyn Fn(&SamplePlan, &dyn Progress, Option<Film>) -> PassOutput + 'a;

/// What one pass over the image leaves.
struct PassOutput {
    film: Film,
    rays: RayCounts,
    /// Per pixel, what its samples met, where the plan reads it ([`SamplePlan::records_work`];
    /// else empty).
    work: Vec<PixelWork>,
}

/// What one pixel's samples met in a pass.
#[derive(Clone, Copy, Debug, Default)]
struct PixelWork {
    /// Rays traced, of all kinds, and the shadow rays shafts spared: the pixel's cost
    /// ([`integrator::RayCounts::work`]).
    rays: u32,

    /// Some shadow ray towards an area light arrived (wholly or in part).
    lit: bool,
    /// Some shadow ray towards an area light was stopped (wholly or in part).
    shadowed: bool,
}

impl PixelWork {
    fn merge(&mut self, other: PixelWork) {
        self.rays = self.rays.saturating_add(other.rays);
        self.lit |= other.lit;
        self.shadowed |= other.shadowed;
    }
}

/// Adaptive sampling in two passes. A pilot of one sample per pixel, with
/// [`pilot_light_rays`] shadow rays per area light, shows where the image changes (edges,
/// textures, noise), what a sample costs and where the penumbrae are. Everything it
/// decides for a pixel is read from the pixel's neighbours, not from the pixel itself (but
/// on the image's frame, below), so the pixel's own pilot sample is independent of its
/// decisions and may stay in its mean without bias (a pixel's own value deciding how long
/// it is sampled is the usual adaptive bias):
/// - near a penumbra (within [`PENUMBRA_REACH`], some other pixel's shadow ray towards an
///   area light arrived and some other's was stopped) the pilot sample is left out and
///   fresh samples cover the light grid ([`LightSamples::Cover`]), unless every area light
///   follows POV-Ray's adaptive rule, which the pilot shades as the render does
///   ([`pilot_is_a_sample`]): then it stays there too;
/// - elsewhere every shadow ray around agreed, so one shadow ray per sample is exact: the
///   pilot sample stays, and the pixel's later samples take the positions after its
///   ([`PositionPlan`]);
/// - on the image's frame, where an edge can hide beyond the border, the pixel's own pilot
///   value counts in its change too ([`change_with_own`]), so its pilot sample is left out
///   and its samples take a sequence of their own ([`PilotSample::Judged`]);
/// - all share the time `spp` samples each would take (`spp - 1` where the pilot stays) as
///   [`allocate`] says.
///
/// A shard (`share`) takes the same fraction of every pixel's count, and the shard that
/// starts at sample 0 holds the pilot samples that stay; a resumed render takes each
/// pixel's samples after those its checkpoint holds. Every render of a part repeats the
/// pilot, which is deterministic, so the parts sum to the whole render exactly.
fn adaptive_passes(
    options: &RenderOptions,
    scene: AdaptiveScene,
    share: Share,
    checkpoint: Option<&Film>,
    run: &Pass,
    progress: &dyn Progress,
) -> (Film, RayCounts, u64) {
    let average = options
        .average_spp
        .unwrap_or(f64::from(options.samples_per_pixel.max(1)));
    let at_corners =
        options.corner_pilot && scene.corner_pilot && average >= corners::CORNERS_FROM_SPP;
    let Pilot {
        film: mut pilot,
        mut rays,
        pixels,
        control,
        spent,
    } = if at_corners {
        corner_pilot(options, run, average)
    } else {
        pilot_pass(options, run, scene.pilot_is_a_sample)
    };
    let w = pilot.width;
    let shown = |i: usize| {
        let win = options.window.as_ref();
        win.is_none_or(|win| win.contains(i % w, i / w))
    };
    // The pilot samples that stay are this render's (or its checkpoint's) when it starts at 0.
    let first_shard = share.range.start == 0;
    let holds_pilot = |i: usize| first_shard && pixels[i].keeps_pilot() && shown(i);
    let budget = average - spent;
    let counts = allocate(&pixels, budget, scene.floor_share);
    let one_ray: Vec<bool> = pixels.iter().map(|p| p.one_ray).collect();
    let pilots: Vec<PilotSample> = pixels.iter().map(|p| p.pilot).collect();
    let resume_at = checkpoint.map_or_else(Vec::new, |c| {
        let held = |i: usize| c.pixels[i].count.saturating_sub(u32::from(holds_pilot(i)));
        (0..counts.len())
            .map(|i| share.of(counts[i]).start + held(i))
            .collect()
    });
    let before = checkpoint.map_or(0, Film::samples);
    let mut film = match checkpoint {
        Some(done) => done.clone(),
        // The corner pilot's film is empty already ([`emptied`]).
        None if at_corners => pilot,
        None => {
            progress.pass(&pilot);
            keep_only(&mut pilot, holds_pilot);
            pilot
        }
    };
    let passes = if options.passes {
        doubling(share.range.clone())
    } else {
        vec![share.range.clone()]
    };
    for range in passes {
        let plan = SamplePlan::PerPixel {
            counts: &counts,
            seed: options.seed,
            one_ray: &one_ray,
            share: Share { range, ..share },
            resume_at: &resume_at,
            positions: Positions {
                seed: options.seed,
                first: FirstPoints::AfterPilot(&pilots),
            },
            control: control.as_ref(),
        };
        let more = run(&plan, progress, Some(film));
        rays.add(&more.rays);
        film = more.film;
        if progress.cancelled() {
            break;
        }
        progress.pass(&film);
    }
    let samples = film.samples() - before;
    (film, rays, samples)
}

/// Clears the pixels of `film` for which `keep` is false.
fn keep_only(film: &mut Film, keep: impl Fn(usize) -> bool + Sync) {
    film.pixels
        .par_iter_mut()
        .enumerate()
        .filter(|(i, _)| !keep(*i))
        .for_each(|(_, pixel)| *pixel = PixelSum::default());
    let w = film.width;
    film.non_finite
        .retain(|&(x, y)| keep(y as usize * w + x as usize));
}

/// What the adaptive pilot leaves: its film, its rays, what it decided per pixel, the
/// corners' control variate where it was taken at the corners, and the samples per pixel
/// its rays took from the budget without going into any mean (the corners'; the pixels'
/// pilot samples are counted in [`allocate`]).
struct Pilot {
    film: Film,
    rays: RayCounts,
    pixels: Vec<AdaptivePixel>,
    control: Option<corners::Control>,
    spent: f64,
}

/// What adaptive sampling reads from the scene before its pilot.
#[derive(Clone, Copy, Debug)]
struct AdaptiveScene {
    /// [`pilot_is_a_sample`].
    pilot_is_a_sample: bool,
    /// Every pixel takes at least 1 / floor_share of the samples ([`allocate`]).
    floor_share: u32,
    /// The pilot may be taken at the pixels' corners ([`corners`]): a sample varies only
    /// with its point in the pixel (no hidden noise), through a pinhole camera, and no
    /// light is an area light (their penumbrae take fresh samples whichever the pilot, and
    /// the corners gained nothing there: 640x480, RMSE at 4 / 6 / 8 spp, soft_shadow +6 /
    /// +1 / -3%, area_grid_6x2 +14 / +10 / +1%, area_circular_9x9 +5 / -1 / -4%).
    corner_pilot: bool,
}

impl AdaptiveScene {
    fn of(scene: &PreparedScene, options: &RenderOptions) -> AdaptiveScene {
        AdaptiveScene {
            pilot_is_a_sample: pilot_is_a_sample(scene, options),
            floor_share: if hidden_noise(scene) {
                FLOOR_SHARE
            } else {
                PLAIN_FLOOR_SHARE
            },
            corner_pilot: !hidden_noise(scene)
                && scene.camera.aperture == 0.0
                && scene.mesh_camera.is_none()
                && scene.lights.iter().all(|l| l.area.is_none()),
        }
    }
}

/// Every pixel's least share of the samples where the scene has noise that a pilot
/// sample's neighbours need not show, and where it has none ([`hidden_noise`]). Measured
/// at 640x480 against POV-Ray, 2 seeds, RMSE at 4 / 8 / 16 spp with an eighth against a
/// quarter: checker 0.00291 / 0.00194 / 0.00152 against 0.00320 / 0.00202 / 0.00147,
/// shape_quadrics 0.00076 / 0.00055 / 0.00045 against 0.00093 / 0.00059 / 0.00046,
/// pattern_gradient 0.00554 / 0.00339 / 0.00209 against 0.00634 / 0.00359 / 0.00221,
/// reflection 0.00066 / 0.00044 / 0.00034 against 0.00077 / 0.00047 / 0.00035, glass and
/// csg_operations within 2%, and the three area-light scenes without jitter 1-5% lower; but
/// focal_blur 7-12% higher (0.0244 / 0.0168 / 0.0127 against 0.0226 / 0.0155 / 0.0113) and
/// area_illumination, whose light is jittered, 3% higher. No floor at all lost at 16 spp
/// (checker 0.00180, csg_operations 0.00401).
const FLOOR_SHARE: u32 = 4;
/// [`FLOOR_SHARE`] for scenes without hidden noise.
const PLAIN_FLOOR_SHARE: u32 = 8;

/// Whether a sample's value varies, beyond its position in the pixel, in ways that the
/// pilot's one sample per neighbour can miss: a lens sampled one ray a sample (under
/// POV-Ray's measured rule a sample averages 7 to 37 rays spread over the lens: at 640x480
/// scenes/focal_blur.pov's RMSE at 4 and 6 spp is 1-3.5% lower with the eighth), a jittered area light
/// (away from penumbrae too), media, radiosity, photons, dispersion. Area lights' shadows
/// are not among them: the pilot finds their penumbrae and treats them apart.
fn hidden_noise(scene: &PreparedScene) -> bool {
    scene.camera.aperture > 0.0 && camera::lens_rule(&scene.camera).is_none()
        || scene
            .lights
            .iter()
            .any(|l| l.area.as_ref().is_some_and(|a| a.jitter))
        || !scene.media.is_empty()
        || scene.settings.radiosity.is_some()
        || scene.settings.photons.is_some() && !scene.world.photon_targets().is_empty()
        || scene.materials.iter().any(|m| m.interior.disperses())
}

/// Whether the adaptive pilot's sample is shaded as the render's samples near a penumbra
/// are, so that it can stay there too: where every area light follows POV-Ray's `adaptive`
/// rule, which the pilot evaluates as the render does (its fixed shadow rays are for the
/// other area lights, whose render samples cover the grid instead).
fn pilot_is_a_sample(scene: &PreparedScene, options: &RenderOptions) -> bool {
    options.area_lights == AreaLightMode::Pov
        && scene.lights.iter().all(|l| {
            l.area
                .as_ref()
                .is_none_or(|a| a.adaptive.is_some() && !l.area_illumination)
        })
}

/// The pilot of [`adaptive_passes`] over the whole image and the decisions read from it;
/// with `exact`, its samples stay near penumbrae too ([`pilot_is_a_sample`]).
fn pilot_pass(options: &RenderOptions, run: &Pass, exact: bool) -> Pilot {
    let PassOutput { film, rays, work } = run(&pilot_plan(options), &(), None);
    let w = film.width;
    // Shadow rays around the pixel (itself left out) that arrived, and that were stopped.
    let around = |flag: fn(&PixelWork) -> bool| {
        let own: Vec<u32> = work.iter().map(|p| u32::from(flag(p))).collect();
        let sums = window_sums(&own, w, PENUMBRA_REACH);
        sums.into_iter()
            .zip(own)
            .map(|(s, o)| s > o)
            .collect::<Vec<bool>>()
    };
    // A pixel is near a penumbra where both kinds are around; without area lights (or
    // without a shadow of one) none is, and the windows are not summed.
    let penumbrae = work.iter().any(|p| p.lit) && work.iter().any(|p| p.shadowed);
    let near_penumbra: Vec<bool> = if penumbrae {
        let (lit, shadowed) = (around(|p| p.lit), around(|p| p.shadowed));
        lit.iter().zip(&shadowed).map(|(l, s)| l & s).collect()
    } else {
        Vec::new()
    };
    let values: Vec<[f32; 3]> = film
        .pixels
        .par_iter()
        .map(|p| p.mean().map(|v| v as f32))
        .collect();
    let h = film.height;
    let pixels = per_neighbourhood(w, h, |i, near| {
        let one_ray = !near_penumbra.get(i).copied().unwrap_or(false);
        let frame = on_frame(w, h, i);
        AdaptivePixel {
            change: if frame {
                change_with_own(&values, near, i)
            } else {
                neighbour_change(&values, near)
            },
            cost: neighbour_cost(&work, near),
            one_ray,
            pilot: if frame {
                PilotSample::Judged
            } else if exact || one_ray {
                PilotSample::Stays
            } else {
                PilotSample::LeftOut
            },
        }
    });
    Pilot {
        film,
        rays,
        pixels,
        control: None,
        spent: 0.0,
    }
}

/// The adaptive pilot at the pixels' corners ([`corners`]) in two passes: every other
/// corner across and down, then the other corners of the 2 x 2 blocks of pixels where
/// those change ([`corners::refinement`]) for an average of `average` samples per pixel.
/// None of its samples is a pixel's, so the film it leaves is empty.
fn corner_pilot(options: &RenderOptions, run: &Pass, average: f64) -> Pilot {
    let seed = options.seed ^ CORNER_SEED;
    let (cw, ch) = (options.width + 1, options.height + 1);
    let coarse = corners::coarse(cw, ch);
    let first = run(
        &SamplePlan::Lattice {
            seed,
            traced: &coarse,
        },
        &(),
        None,
    );
    let rest = corners::refinement(&first.film, corners::refine_threshold(average));
    let more = run(
        &SamplePlan::Lattice {
            seed,
            traced: &rest,
        },
        &(),
        Some(first.film),
    );
    let mut rays = first.rays;
    rays.add(&more.rays);
    let mut work = first.work;
    for (a, b) in work.iter_mut().zip(more.work) {
        a.merge(b);
    }
    let (pixels, control) = corners::corner_pixels(&more.film, &mut work);
    // The passes' rays in samples of a pixel's mean cost (their total over the pixels'
    // summed costs): the corners traced again lie where the image changes, whose rays
    // cost more than the average corner's.
    let costs: f64 = pixels.iter().map(|p| p.cost).sum();
    Pilot {
        film: emptied(more.film, options.width, options.height),
        spent: rays.work() as f64 / costs.max(1.0),
        rays,
        pixels,
        control: Some(control),
    }
}

/// An empty w x h film in the memory of a larger one (the corner pass's): a new film's
/// first touch of its pages was 2.5% of a 6 spp 640x480 render of scenes/checker.pov.
fn emptied(mut film: Film, w: usize, h: usize) -> Film {
    film.pixels.truncate(w * h);
    film.pixels
        .par_iter_mut()
        .for_each(|p| *p = PixelSum::default());
    film.width = w;
    film.height = h;
    film.non_finite.clear();
    film
}

/// Scrambles the corner pass's values apart from the pixels' samples.
const CORNER_SEED: u64 = 0xc0_7e75_5eed_0001;

/// The adaptive pilot: one sample per pixel, its light sampling and its values apart from
/// the render's.
fn pilot_plan(options: &RenderOptions) -> SamplePlan<'static> {
    SamplePlan::Uniform {
        spp: 1,
        range: 0..1,
        first: 0,
        checkpoint: None,
        seed: options.seed ^ 0xad47_1be5_5eed_0001,
        // But its position is the render's own: point 0 of the sequence whose next
        // points the pixel's later samples take where the pilot sample stays.
        position_seed: options.seed,
        fixed_light: Some(pilot_light_rays(options.samples_per_pixel)),
    }
}

/// A render's part of each pixel's samples: samples `range` of `spp`, scaled to each
/// pixel's own count, so that shards whose ranges tile 0..spp tile every pixel's samples.
#[derive(Clone, Debug)]
struct Share {
    range: Range<u32>,
    spp: u32,
}

impl Share {
    /// Every sample of every pixel.
    const ALL: Share = Share {
        range: 0..1,
        spp: 1,
    };

    /// This part of `count` samples.
    fn of(&self, count: u32) -> Range<u32> {
        if self.range == (0..self.spp) {
            // The whole, without two divisions a pixel.
            return 0..count;
        }
        let scale = |k: u32| (u64::from(k) * u64::from(count) / u64::from(self.spp)) as u32;
        scale(self.range.start)..scale(self.range.end)
    }
}

/// Which samples each pixel takes.
enum SamplePlan<'a> {
    /// Every pixel takes samples `range` of `spp`, except those a checkpoint holds (its
    /// count of them from `first` on); with `fixed_light`, that many shadow rays per area
    /// light per sample whatever the render's light sampling.
    Uniform {
        spp: u32,
        range: Range<u32>,
        first: u32,
        checkpoint: Option<&'a Film>,
        seed: u64,
        /// The seed of the pixel positions' sequences (sample i takes point i).
        position_seed: u64,
        fixed_light: Option<u32>,
    },
    /// The adaptive pilot at the pixels' corners ([`corners`]): one sample near each
    /// point of the (w + 1) x (h + 1) grid of the pixels' corners that `traced` marks (in
    /// scenes without area lights: [`AdaptiveScene`]).
    Lattice { seed: u64, traced: &'a [bool] },
    /// Adaptive sampling: pixel i has counts[i] samples (all of its own strata; none
    /// where the count is 0) and takes those of its `share` from `resume_at[i]` on (a
    /// checkpoint holds those before; empty: none), with one shadow ray per light per
    /// sample where one_ray[i], their positions as `positions` says.
    PerPixel {
        counts: &'a [u32],
        seed: u64,
        one_ray: &'a [bool],
        share: Share,
        resume_at: &'a [u32],
        positions: Positions<'a>,
        /// The corners' control variate, where the pilot was taken at the corners.
        control: Option<&'a corners::Control>,
    },
}

/// Where a per-pixel plan's samples take their positions: the sequences of `seed`, each
/// pixel's from the point `first` says on.
struct Positions<'a> {
    seed: u64,
    first: FirstPoints<'a>,
}

impl Positions<'_> {
    /// Where pixel `i`'s sample 0 takes its position.
    fn of(&self, i: usize) -> PositionPlan {
        let at = |seed, first| PositionPlan { seed, first };
        match self.first {
            FirstPoints::AfterPilot(pilots) => match pilots[i] {
                PilotSample::Stays => at(self.seed, 1),
                PilotSample::LeftOut => at(self.seed, 0),
                PilotSample::Judged => at(self.seed ^ JUDGED_POSITIONS, 0),
            },
            FirstPoints::Listed(first) => at(self.seed, first[i]),
        }
    }
}

/// Where a per-pixel plan's sample 0 of each pixel takes its position: after the points
/// the pixel's earlier samples took, so that together they stay one stratified set.
enum FirstPoints<'a> {
    /// After the adaptive pilot's point 0 where the pilot sample stays, else from 0 (of a
    /// sequence of their own where the pilot sample was [`PilotSample::Judged`]).
    AfterPilot(&'a [PilotSample]),
    /// At each pixel's listed point (the samples that earlier passes took).
    Listed(&'a [u32]),
}

/// One pixel's part of a plan.
struct PixelPlan {
    spp: u32,
    range: Range<u32>,
    seed: u64,
    /// Shade with the pass's fixed-count integrator (one shadow ray per area light, or the
    /// pilot's [`pilot_light_rays`]) instead of the render's own light sampling.
    fixed_light: bool,
    position: PositionPlan,
}

/// Where a pixel's samples take their positions: sample i takes point `first + i` of the
/// pixel's position sequence under `seed` ([`PixelSampler::pixel_position`]). A pilot
/// sample that stays in the pixel's mean is point 0 of the sequence the pixel's later
/// samples continue, so that together they are stratified as one set of samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct PositionPlan {
    seed: u64,
    first: u32,
}

impl SamplePlan<'_> {
    /// Whether the pass records each pixel's work: only the adaptive pilot's (the uniform
    /// plan with a fixed light count) is read, and a render's other passes need not fill
    /// 8 bytes a pixel.
    fn records_work(&self) -> bool {
        matches!(
            self,
            SamplePlan::Uniform {
                fixed_light: Some(_),
                ..
            } | SamplePlan::Lattice { .. }
        )
    }

    /// The grid of points the pass samples, for a w x h image: its pixels, or their corners.
    fn grid(&self, w: usize, h: usize) -> (usize, usize) {
        match self {
            SamplePlan::Lattice { .. } => (w + 1, h + 1),
            _ => (w, h),
        }
    }

    /// The sample indices some pixel of the plan takes (a superset): the photon passes a
    /// render shoots, so a shard of an adaptive render shoots only its part's.
    fn index_span(&self) -> Range<u32> {
        match self {
            SamplePlan::Uniform { range, .. } => range.clone(),
            SamplePlan::Lattice { .. } => 0..1,
            SamplePlan::PerPixel { counts, .. } => (0..counts.len())
                .map(|i| self.pixel(i).range)
                .filter(|r| !r.is_empty())
                .reduce(|a, b| a.start.min(b.start)..a.end.max(b.end))
                .unwrap_or(0..0),
        }
    }

    fn seed(&self) -> u64 {
        match self {
            SamplePlan::Uniform { seed, .. }
            | SamplePlan::Lattice { seed, .. }
            | SamplePlan::PerPixel { seed, .. } => *seed,
        }
    }

    fn pixel(&self, i: usize) -> PixelPlan {
        match self {
            SamplePlan::Uniform {
                spp,
                range,
                first,
                checkpoint,
                seed,
                position_seed,
                fixed_light,
            } => {
                let done = checkpoint.map_or(0, |c| c.pixels[i].count);
                PixelPlan {
                    spp: *spp,
                    range: range.start.max(first + done)..range.end,
                    seed: *seed,
                    fixed_light: fixed_light.is_some(),
                    position: PositionPlan {
                        seed: *position_seed,
                        first: 0,
                    },
                }
            }
            &SamplePlan::Lattice { seed, traced } => PixelPlan {
                spp: 1,
                range: 0..u32::from(traced[i]),
                seed,
                fixed_light: false,
                position: PositionPlan { seed, first: 0 },
            },
            SamplePlan::PerPixel {
                counts,
                seed,
                one_ray,
                share,
                resume_at,
                positions,
                ..
            } => {
                let part = share.of(counts[i]);
                let first = part.start.max(resume_at.get(i).copied().unwrap_or(0));
                PixelPlan {
                    spp: counts[i].max(1),
                    range: first.min(part.end)..part.end,
                    seed: *seed,
                    fixed_light: one_ray[i],
                    position: positions.of(i),
                }
            }
        }
    }
}

/// The noise around each pixel after a pilot: the largest pilot deviation among its eight
/// neighbours. A pilot of a few samples can miss noise that is there (four light samples
/// that happen to agree), hence the neighbourhood; the pixel itself is left out so that
/// what is decided from this does not depend on its own samples, which stay in its mean.
fn neighbour_noise(pilot: &Film) -> Vec<f64> {
    let sigma: Vec<f64> = pilot.pixels.iter().map(sample_deviation).collect();
    per_neighbourhood(pilot.width, pilot.height, |_, near| {
        near.iter().map(|&j| sigma[j]).fold(0.0, f64::max)
    })
}

/// How much the image changes around a pixel after a one-sample pilot: the range of its
/// neighbours' values (`near`; largest minus smallest, averaged over the channels). An
/// edge or a texture between them shows, and so does noise; the pixel itself is left out.
/// In single precision, which is ample for a share of samples, and in one pass with the
/// cost: with a pass each over double-precision copies, the analysis took 71 ms of a
/// one-sample 1280x960 adaptive render of scenes/checker.pov (0.52 s), this way 52 ms.
fn neighbour_change(values: &[[f32; 3]], near: &[usize]) -> f64 {
    let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
    for v in near.iter().map(|&j| values[j]) {
        // As f32::min and max (a NaN is passed over), without their NaN tests: this loop
        // was most of the pilot's analysis.
        for c in 0..3 {
            if v[c] < lo[c] {
                lo[c] = v[c];
            }
            if v[c] > hi[c] {
                hi[c] = v[c];
            }
        }
    }
    (0..3)
        .map(|c| f64::from((hi[c] - lo[c]).max(0.0)))
        .sum::<f64>()
        / 3.0
}

/// Whether pixel `i` of a w x h image lies on its one-pixel frame.
fn on_frame(w: usize, h: usize, i: usize) -> bool {
    let (x, y) = (i % w, i / w);
    x == 0 || y == 0 || x + 1 == w || y + 1 == h
}

/// The change around a pixel of the image's frame, its own pilot value counted in (its
/// pilot sample is then left out of its mean, as near a penumbra, so that nothing decided
/// from it is averaged with it). Beyond the frame there are no neighbours: an edge that runs
/// along the frame, its other side outside, shows in no neighbour of the pixels it crosses,
/// and they kept their one pilot sample. scenes/checker.pov at 640x480, 6 spp, held 7-31%
/// of its squared error in the frame (0.7% of the pixels; 5 seeds) so; counting the pixel's
/// own value, 6-11%, and the RMSE over the five 0.00241 -> 0.00225.
fn change_with_own(values: &[[f32; 3]], near: &[usize], own: usize) -> f64 {
    let mut with_own = [0; 9];
    with_own[..near.len()].copy_from_slice(near);
    with_own[near.len()] = own;
    neighbour_change(values, &with_own[..=near.len()])
}

/// The rays a sample costs around a pixel: the mean over its neighbours' (`near`) pilot
/// samples (at least 1), the pixel itself left out.
fn neighbour_cost(work: &[PixelWork], near: &[usize]) -> f64 {
    let rays: f64 = near.iter().map(|&j| f64::from(work[j].rays)).sum();
    (rays / f64::max(near.len() as f64, 1.0)).max(1.0)
}

/// Per pixel (rows of `w`), the sum of `values` over the (2r + 1) square around it, clipped
/// at the borders. Separable: rows first, then columns.
fn window_sums(values: &[u32], w: usize, r: usize) -> Vec<u32> {
    let h = values.len() / w.max(1);
    let reach = |n: usize, i: usize| i.saturating_sub(r)..(i + r + 1).min(n);
    let rows: Vec<u32> = (0..values.len())
        .map(|i| reach(w, i % w).map(|x| values[i - i % w + x]).sum())
        .collect();
    (0..values.len())
        .map(|i| reach(h, i / w).map(|y| rows[y * w + i % w]).sum())
        .collect()
}

/// `f` of each pixel (its index) and its neighbours in a w x h image (row-major): the
/// pixels of the 3 x 3 block around it, itself left out (fewer at the borders). Plain loops
/// and arrays: over a 640x480 pilot, iterators of iterators cost 1,300 instructions a
/// pixel. Rows in parallel: on one thread the analysis was a tenth of a one-sample render.
fn per_neighbourhood<T: Copy + Default + Send + Sync>(
    w: usize,
    h: usize,
    f: impl Fn(usize, &[usize]) -> T + Sync,
) -> Vec<T> {
    let mut out = film::filled(T::default(), w * h);
    out.par_chunks_mut(w.max(1))
        .enumerate()
        .for_each(|(y, row)| {
            for (x, slot) in row.iter_mut().enumerate() {
                let (near, n) = neighbours(w, h, x, y);
                *slot = f(y * w + x, &near[..n]);
            }
        });
    out
}

/// The neighbours of pixel (x, y) ([`per_neighbourhood`]) and how many there are; inside
/// the borders, fixed offsets.
#[inline]
fn neighbours(w: usize, h: usize, x: usize, y: usize) -> ([usize; 8], usize) {
    let i = y * w + x;
    if x > 0 && y > 0 && x + 1 < w && y + 1 < h {
        let (a, b) = (i - w, i + w);
        return ([a - 1, a, a + 1, i - 1, i + 1, b - 1, b, b + 1], 8);
    }
    let mut near = [0; 8];
    let mut n = 0;
    for yy in y.saturating_sub(1)..(y + 2).min(h) {
        for xx in x.saturating_sub(1)..(x + 2).min(w) {
            let j = yy * w + xx;
            if j != i {
                near[n] = j;
                n += 1;
            }
        }
    }
    (near, n)
}

/// The standard deviation of one sample of the pixel, over the three channels (0 with fewer
/// than two samples).
fn sample_deviation(p: &PixelSum) -> f64 {
    let v = p.variance_of_mean();
    (f64::from(p.count) * (v[0] + v[1] + v[2]) / 3.0).sqrt()
}

/// What the adaptive pilot found around one pixel.
#[derive(Clone, Copy, Default)]
struct AdaptivePixel {
    /// How much the neighbours' values differ ([`neighbour_change`]).
    change: f64,
    /// Rays per (one-ray) sample.
    cost: f64,
    /// No penumbra near: one shadow ray per sample.
    one_ray: bool,
    /// What becomes of the pixel's pilot sample.
    pilot: PilotSample,
}

impl AdaptivePixel {
    fn keeps_pilot(&self) -> bool {
        self.pilot == PilotSample::Stays
    }
}

/// What becomes of a pixel's adaptive pilot sample.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum PilotSample {
    /// It stays in the pixel's mean, and the pixel's later samples take the points after
    /// its point 0 (one-ray pixels, and every pixel where the pilot's sample is shaded as
    /// the render's, but on the frame).
    #[default]
    Stays,
    /// Left out (near a penumbra, where the pilot shades apart from the render), or none
    /// (a pilot at the pixels' corners: [`corners`]): the pixel's samples take its
    /// sequence from point 0.
    LeftOut,
    /// Left out because its value went into the pixel's own decisions (on the image's
    /// frame: [`change_with_own`]). The pixel's samples then take a sequence of their own:
    /// points of the pilot's sequence are not independent of its point 0 (point 0 itself,
    /// or point 1 in the other half of the pixel), and a count chosen from the pilot's
    /// value would bias them.
    Judged,
}

/// Scrambles the position sequences of [`PilotSample::Judged`] pixels apart from the pilot's.
const JUDGED_POSITIONS: u64 = 0x6a75_6467_6564_0001;

/// The samples each pixel takes after the pilot. Every pixel takes 1 / `floor_share` of
/// `spp` (a quarter, or an eighth in a scene without hidden noise: [`AdaptiveScene`]; at
/// least one where the pilot sample is left out, near a penumbra: the change around a pixel
/// is only a sign of its noise, and in an out-of-focus blur eight neighbours of one sample
/// each can agree by chance), and they share the time the rest would take so that the
/// samples pixel i holds beyond its floor, n_i, go as s_i / sqrt(c_i), its noise s (the
/// change around it stands for it) over the root of its cost c per sample, which minimises
/// their summed variance sum s_i^2 / n_i for the time sum n_i c_i. A pilot sample that
/// stays counts in n_i: a pixel whose share is below it takes no more ([`water_level`]).
/// (Before, the samples after the pilot went as s_i / sqrt(c_i), spread over more pixels.
/// Counting the pilot, RMSE at 640x480 against POV-Ray, 2 seeds, at 1.125 / 1.5 / 2 / 3
/// spp: shape_quadrics -18 / -9 / -7 / -6%, pattern_gradient -15 / -15 / -10 / -8%,
/// reflection -12 / -6 / -3 / 0%, soft_shadow +5 / -4 / -8 / -6%, area_circular_9x9
/// +5 / -5 / -7 / -5%, checker +2 / -1 / -1 / 0%, but focal_blur -8 / +6 / +5 / +3% and
/// csg_operations -8 / +7 / +2 / 0%.) (Measured at 640x480, 16 spp: with no quarter,
/// focal_blur's RMSE was 0.0180, with it 0.0119; checker's 0.00198 and 0.00186.) Pixels near a
/// penumbra share too: there the error is on the hard edges each grid point's shadow draws
/// (area_grid_6x2 at 16 spp: 3.3% of the pixels hold 99% of the squared error), and
/// giving every such pixel `spp` spent most of their time on the smooth parts between
/// (with the share, area_grid_6x2's RMSE at 16 spp fell from 0.00156 to 0.00060).
fn allocate(pixels: &[AdaptivePixel], average: f64, floor_share: u32) -> Vec<u32> {
    let spp = average.ceil() as u32;
    let least = (spp / floor_share).min(spp - 1);
    // Where the pilot is left out (near a penumbra): at least one sample of the pixel's own.
    let floor = |p: &AdaptivePixel| if p.keeps_pilot() { least } else { least.max(1) };
    let full = |p: &AdaptivePixel| {
        if p.keeps_pilot() {
            average - 1.0
        } else {
            average
        }
    };
    let time: f64 = pixels
        .iter()
        .map(|p| p.cost * (full(p) - f64::from(floor(p))))
        .sum();
    // Weights change / sqrt(cost), so that time shares go as change x sqrt(cost).
    let spent: f64 = pixels.iter().map(|p| p.change * p.cost.sqrt()).sum();
    let held = |p: &AdaptivePixel| f64::from(u8::from(p.keeps_pilot()));
    let more = |t: f64, p: &AdaptivePixel| (t * p.change / p.cost.sqrt() - held(p)).max(0.0);
    let scale = if spent > 0.0 {
        water_level(pixels, time, spent)
    } else {
        0.0
    };
    pixels
        .par_iter()
        .map(|p| {
            if spent > 0.0 {
                floor(p) + more(scale, p).round() as u32
            } else {
                // No change anywhere: the whole count (a fractional average's floor).
                full(p) as u32
            }
        })
        .collect()
}

/// The scale t at which pixels that take t w_i samples in all (w_i = change / sqrt(cost)),
/// less the pilot sample where it stays, spend `time` (sum of cost x samples): `spent` is
/// the sum of cost x w_i. The time is convex in t (a sum of hinges), so Newton's steps from
/// above come down to the level without passing it, exactly once the pixels that take
/// samples stop changing (five steps at 640x480); over single-precision copies, summed in
/// eight lanes so that the compiler vectorises each pass (16 M instructions at 640x480,
/// 1.2% of a render at 1.0625 spp; 35 M with 24 steps of bisection).
fn water_level(pixels: &[AdaptivePixel], time: f64, spent: f64) -> f64 {
    let lane = |f: fn(&AdaptivePixel) -> f32| -> Vec<f32> { pixels.iter().map(f).collect() };
    let weights = &lane(|p| (p.change / p.cost.sqrt()) as f32);
    let costs = &lane(|p| p.cost as f32);
    let held = &lane(|p| f32::from(u8::from(p.keeps_pilot())));
    // The time at t and its slope there.
    let time_at = |t: f32| -> (f64, f64) {
        let (mut sums, mut slopes) = ([0.0f32; 8], [0.0f32; 8]);
        let mut add = |k: usize, w: f32, c: f32, h: f32| {
            let more = t * w - h;
            let on = more > 0.0;
            sums[k] += if on { c * more } else { 0.0 };
            slopes[k] += if on { c * w } else { 0.0 };
        };
        let chunks = weights.chunks_exact(8).zip(costs.chunks_exact(8));
        for ((w, c), h) in chunks.zip(held.chunks_exact(8)) {
            for k in 0..8 {
                add(k, w[k], c[k], h[k]);
            }
        }
        for k in weights.len() / 8 * 8..weights.len() {
            add(0, weights[k], costs[k], held[k]);
        }
        let total = |v: [f32; 8]| v.iter().map(|&x| f64::from(x)).sum::<f64>();
        (total(sums), total(slopes))
    };
    // Held samples only lower what the scale buys: at this t the time is at least `time`.
    let held_time: f64 = costs.iter().zip(held).map(|(c, h)| f64::from(c * h)).sum();
    let mut t = (time + held_time) / spent;
    for _ in 0..32 {
        let (at, slope) = time_at(t as f32);
        let step = (at - time) / slope;
        // Done, or no pixel takes samples at this t (no slope: a budget of none).
        if step.is_nan() || step <= 1e-6 * t {
            break;
        }
        t -= step;
    }
    t
}

/// Where the sample `sampler` has started lies in pixel (x, y) of a w x h image: its point
/// in the pixel, and the screen coordinates (in [-1/2, 1/2], y up) a camera takes.
fn sample_position(
    layout: &dimensions::DimensionLayout,
    (x, y, w, h): (usize, usize, usize, usize),
    sampler: &mut PixelSampler,
) -> ((f64, f64), (f64, f64)) {
    sampler.set_dimension(layout.dimension(0, Purpose::PixelPosition));
    let (u, v) = sampler.pixel_position();
    let screen = (
        (x as f64 + u) / w as f64 - 0.5,
        0.5 - (y as f64 + v) / h as f64,
    );
    ((u, v), screen)
}

/// The camera ray of the sample `sampler` has started, for pixel (x, y) of a w x h image,
/// and where in the pixel it starts.
fn sample_camera_ray(
    scene: &PreparedScene,
    layout: &dimensions::DimensionLayout,
    (x, y, w, h): (usize, usize, usize, usize),
    sampler: &mut PixelSampler,
) -> ((f64, f64), Option<Ray>) {
    let (in_pixel, (sx, sy)) = sample_position(layout, (x, y, w, h), sampler);
    if let Some(mesh) = &scene.mesh_camera {
        return (in_pixel, mesh.ray((x, y, w, h), in_pixel));
    }
    // A pinhole draws no lens point (its dimensions are fixed, so nothing later moves).
    let lens = if scene.camera.aperture > 0.0 {
        sampler.set_dimension(layout.dimension(0, Purpose::Lens));
        sampler.get_2d()
    } else {
        (0.5, 0.5)
    };
    (in_pixel, camera_ray(&scene.camera, sx, sy, lens))
}

/// One sample of a pixel under POV-Ray's adaptive focal blur ([`camera::LensRule`]): the
/// lens's cells traced in POV-Ray's order through one point of the pixel, each once, until
/// the rule stops them, and their mean. POV-Ray's pixel is that mean, whose expectation the
/// stop (which depends on the samples) moves; averaging independent copies of it converges
/// to POV-Ray's image, which a lens sampled one ray at a time cannot (160x120, 4 x 256 spp,
/// scenes/focal_blur.pov: sqrt(B) 0.0018 with the measured lens sampled whole).
fn povray_lens_sample(
    scene: &PreparedScene,
    layout: &dimensions::DimensionLayout,
    rule: camera::LensRule,
    pixel: (usize, usize, usize, usize),
    sampler: &mut PixelSampler,
    mut radiance: impl FnMut(&Ray, &mut PixelSampler) -> DVec3,
) -> DVec3 {
    let (_, (sx, sy)) = sample_position(layout, pixel, sampler);
    let (mut sum, mut squares) = (DVec3::ZERO, DVec3::ZERO);
    let mut checks = rule.checks.iter().peekable();
    let samples = rule.order.len() as u32;
    for j in 0..samples {
        // POV-Ray's sample j, jittered by this sample's own values.
        let mut sub = sampler.subsample(j, samples);
        sub.set_dimension(layout.dimension(0, Purpose::Lens));
        let lens = rule.lens(j as usize, sub.get_2d());
        let l = camera_ray(&scene.camera, sx, sy, lens)
            .map_or(DVec3::ZERO, |ray| radiance(&ray, &mut sub));
        sum += l;
        squares += l * l;
        let n = j + 1;
        if let Some(&(_, threshold)) = checks.next_if(|&&(at, _)| at == n) {
            let nf = f64::from(n);
            let variance = (squares - sum * sum / nf) / (nf - 1.0);
            if variance.max_element() < threshold * rule.scale {
                return sum / nf;
            }
        }
    }
    sum / f64::from(samples)
}

/// Photons shot per pass (per sample index) in a scene with photon targets.
const PHOTONS_PER_PASS: u32 = 50_000;
/// Sample indices whose photon passes are held in memory at once.
const PHOTON_BATCH: u32 = 16;
/// The photon stream whose first pass sets the first gather radius: the same for every
/// seed, so that every seed's render estimates the same thing.
const RADIUS_SEED: u64 = 0;

/// One pass over the image: the film and the rays traced. Cancelled, each pixel stops at a
/// sample boundary and its count says how many of its samples it took. In a scene with
/// photons, the sample indices go in batches, each with its photon passes.
fn render_pass(
    scene: &PreparedScene,
    options: &RenderOptions,
    plan: &SamplePlan,
    progress: &dyn Progress,
    film: Option<Film>,
) -> PassOutput {
    let (gw, gh) = plan.grid(options.width, options.height);
    let mut out = PassOutput {
        film: film.unwrap_or_else(|| Film::new(gw, gh)),
        rays: RayCounts::default(),
        work: if plan.records_work() {
            film::filled(PixelWork::default(), gw * gh)
        } else {
            Vec::new()
        },
    };
    let shooter = Integrator::new(scene, options);
    let first = scene
        .settings
        .photons
        .filter(|_| !scene.world.photon_targets().is_empty())
        .and_then(|_| {
            let shot = shooter.shoot_photons(0, RADIUS_SEED, PHOTONS_PER_PASS);
            let surface = photons::first_radius(&shot.surface);
            let volume = photons::first_beam_radius(&shot.volume);
            // A map that stays empty never uses its radius: the other's stands in.
            Some((surface.or(volume)?, volume.or(surface)?))
        });
    let Some((first_surface, first_volume)) = first else {
        return render_indices(scene, options, plan, None, progress, out);
    };
    let span = plan.index_span();
    let batches: Vec<Range<u32>> = span
        .clone()
        .step_by(PHOTON_BATCH as usize)
        .map(|a| a..(a + PHOTON_BATCH).min(span.end))
        .collect();
    for (i, batch) in batches.iter().enumerate() {
        let maps = photons::PhotonMaps {
            first: batch.start,
            maps: batch
                .clone()
                .into_par_iter()
                .map(|pass| {
                    let shot = shooter.shoot_photons(pass, plan.seed(), PHOTONS_PER_PASS);
                    let radius = |first| photons::pass_radius(first, pass);
                    photons::PassMaps {
                        surface: photons::PhotonMap::new(shot.surface, radius(first_surface)),
                        volume: photons::BeamMap::new(shot.volume, radius(first_volume)),
                    }
                })
                .collect(),
        };
        let photons = PhotonBatch {
            maps: &maps,
            indices: batch.clone(),
            number: (i as u64, batches.len() as u64),
        };
        out = render_indices(scene, options, plan, Some(&photons), progress, out);
        if progress.cancelled() {
            break;
        }
    }
    out
}

/// The sample indices one batch renders, with their photon passes.
struct PhotonBatch<'m> {
    maps: &'m photons::PhotonMaps,
    indices: Range<u32>,
    /// Which batch of how many, for progress.
    number: (u64, u64),
}

/// [`render_pass`] over the samples of one photon batch (all of them without photons).
fn render_indices(
    scene: &PreparedScene,
    options: &RenderOptions,
    plan: &SamplePlan,
    photons: Option<&PhotonBatch>,
    progress: &dyn Progress,
    mut out: PassOutput,
) -> PassOutput {
    let window = match plan {
        // In adaptive mode the one uniform plan is the pilot.
        SamplePlan::Uniform { .. } if options.adaptive => None,
        SamplePlan::Lattice { .. } => None,
        _ => options.window.clone(),
    };
    let grid = plan.grid(options.width, options.height);
    let tiles = pass_tiles(grid.0, grid.1, window.as_ref());
    let (batch, batches) = photons.map_or((0, 1), |p| p.number);
    let (integrator, fixed_integrator) = pass_integrators(scene, options, plan, photons);
    let job = TileJob {
        scene,
        options,
        plan,
        photons,
        window,
        layout: *integrator.layout(),
        grid,
        control: match plan {
            SamplePlan::PerPixel { control, .. } => *control,
            _ => None,
        },
        lens_rule: camera::lens_rule(&scene.camera),
        integrators: [integrator, fixed_integrator],
        progress,
        done: AtomicU64::new(tiles.len() as u64 * batch),
        total: tiles.len() as u64 * batches,
    };
    // Each tile adds to its own rows of the film and work it is given: no film of the
    // tiles' own and no copy (at 640x480 their page faults were a seventh of a one-sample
    // render's time), and a pass that continues a film adds to it in place.
    let w = grid.0;
    let sums = tile_rows(&mut out.film.pixels, w, &tiles);
    let works = tile_rows(&mut out.work, w, &tiles);
    let results: Vec<_> = tiles
        .par_iter()
        .zip(sums.into_par_iter().zip(works))
        .map(|(&corner, rows)| job.tile(corner, rows))
        .collect();
    for (counts, non_finite) in results {
        out.rays.add(&counts);
        out.film.non_finite.extend(non_finite);
    }
    // As `Film::merge` keeps it: the same list whatever the split.
    out.film.non_finite.sort_unstable_by_key(|&(x, y)| (y, x));
    out
}

/// The corners of the tiles of a w x h image that meet the window, row by row.
fn pass_tiles(w: usize, h: usize, window: Option<&PixelWindow>) -> Vec<(usize, usize)> {
    (0..h.div_ceil(TILE))
        .flat_map(|ty| (0..w.div_ceil(TILE)).map(move |tx| (tx * TILE, ty * TILE)))
        .filter(|&(x0, y0)| {
            window.is_none_or(|win| {
                x0 < win.x.end
                    && win.x.start < x0 + TILE
                    && y0 < win.y.end
                    && win.y.start < y0 + TILE
            })
        })
        .collect()
}

/// What every tile of a pass shares.
struct TileJob<'a> {
    scene: &'a PreparedScene,
    options: &'a RenderOptions,
    plan: &'a SamplePlan<'a>,
    photons: Option<&'a PhotonBatch<'a>>,
    window: Option<PixelWindow>,
    layout: dimensions::DimensionLayout,
    /// The points the pass samples: the image's pixels, or their corners
    /// ([`SamplePlan::grid`]).
    grid: (usize, usize),
    /// The corners' control variate of a per-pixel pass after a corner pilot.
    control: Option<&'a corners::Control>,
    /// POV-Ray's rule for the camera's lens samples, where it is measured.
    lens_rule: Option<camera::LensRule>,
    /// The render's own integrator and the fixed-count one ([`pass_integrators`]).
    integrators: [Integrator<'a>; 2],
    progress: &'a dyn Progress,
    /// Tiles done and to do, over the pass's photon batches, for progress.
    done: AtomicU64,
    total: u64,
}

/// What a tile leaves besides its pixels: its rays and its non-finite samples.
type TileOutput = (RayCounts, Vec<(u32, u32)>);

impl TileJob<'_> {
    /// Adds the samples of the tile at `(x0, y0)` to its rows.
    fn tile(&self, (x0, y0): (usize, usize), (mut sums, mut works): TileRows) -> TileOutput {
        let (w, h) = self.grid;
        let mut sampler = self.sampler(1);
        let mut out = (RayCounts::default(), Vec::new());
        for y in y0..(y0 + TILE).min(h) {
            for x in x0..(x0 + TILE).min(w) {
                if !self.window.as_ref().is_none_or(|win| win.contains(x, y)) {
                    continue;
                }
                let plan = self.pixel_plan(x, y);
                // Nothing to add (an adaptive pass leaves many pixels without samples).
                if plan.range.is_empty() {
                    continue;
                }
                let before = out.0;
                let sum = &mut sums[y - y0][x - x0];
                self.pixel((x, y), plan, &mut sampler, sum, &mut out);
                // Rows only where the pass records work.
                let Some(work) = works.get_mut(y - y0) else {
                    continue;
                };
                let counts = &out.0;
                work[x - x0].merge(PixelWork {
                    rays: (counts.work() - before.work())
                        .try_into()
                        .unwrap_or(u32::MAX),
                    lit: counts.area_lit > before.area_lit,
                    shadowed: counts.area_shadowed > before.area_shadowed,
                });
            }
        }
        let n = self.done.fetch_add(1, Ordering::Relaxed) + 1;
        self.progress.advance(n, self.total);
        out
    }

    /// The plan's samples of pixel (x, y) in this batch.
    fn pixel_plan(&self, x: usize, y: usize) -> PixelPlan {
        let plan = self.plan.pixel(y * self.grid.0 + x);
        match self.photons {
            Some(p) => PixelPlan {
                range: plan.range.start.max(p.indices.start)..plan.range.end.min(p.indices.end),
                ..plan
            },
            None => plan,
        }
    }

    /// Adds the samples `plan` gives pixel (x, y) to its `sum`.
    fn pixel(
        &self,
        (x, y): (usize, usize),
        plan: PixelPlan,
        sampler: &mut PixelSampler,
        sum: &mut PixelSum,
        (counts, non_finite): &mut TileOutput,
    ) {
        let PixelPlan {
            spp,
            range,
            seed,
            fixed_light,
            position,
        } = plan;
        if sampler.samples_per_pixel() != spp {
            *sampler = self.sampler(spp);
        }
        let integrator = &self.integrators[usize::from(fixed_light)];
        for index in range {
            if self.progress.cancelled() {
                break;
            }
            sampler.start(x as u32, y as u32, index, seed);
            if position != (PositionPlan { seed, first: 0 }) {
                let point = index + position.first;
                sampler.set_position(x as u32, y as u32, position.seed, point);
            }
            let l = self.sample_value((x, y), sampler, integrator, counts);
            if l.is_finite() {
                sum.add(l.to_array());
            } else {
                sum.add([0.0; 3]);
                non_finite.push((x as u32, y as u32));
            }
        }
    }

    /// The value of the sample `sampler` has started at pixel (x, y), or at the corner
    /// (x, y) in a corner pass.
    fn sample_value(
        &self,
        (x, y): (usize, usize),
        sampler: &mut PixelSampler,
        integrator: &Integrator,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let (w, h) = (self.options.width, self.options.height);
        // No ray (outside a fisheye's circle): black, as POV-Ray renders it.
        let mut trace = |ray: Option<Ray>, sampler: &mut PixelSampler| {
            ray.map_or(DVec3::ZERO, |ray| {
                integrator.radiance(&ray, sampler, counts)
            })
        };
        if let SamplePlan::Lattice { .. } = self.plan {
            // Near the corner ([`corners::CORNER_JITTER`]), through the pinhole (corner
            // pilots are for scenes without a lens: [`AdaptiveScene`]).
            sampler.set_dimension(self.layout.dimension(0, Purpose::PixelPosition));
            let (ju, jv) = sampler.pixel_position();
            let near = |c: usize, j: f64| c as f64 + corners::CORNER_JITTER * (2.0 * j - 1.0);
            let screen = (near(x, ju) / w as f64 - 0.5, 0.5 - near(y, jv) / h as f64);
            return trace(
                camera_ray(&self.scene.camera, screen.0, screen.1, (0.5, 0.5)),
                sampler,
            );
        }
        let pixel = (x, y, w, h);
        if let Some(rule) = self.lens_rule {
            return povray_lens_sample(self.scene, &self.layout, rule, pixel, sampler, |r, s| {
                trace(Some(*r), s)
            });
        }
        let (in_pixel, ray) = sample_camera_ray(self.scene, &self.layout, pixel, sampler);
        let l = trace(ray, sampler);
        match self.control {
            Some(control) => control.apply((x, y), in_pixel, l),
            None => l,
        }
    }

    fn sampler(&self, spp: u32) -> PixelSampler {
        if self.options.stratified {
            PixelSampler::new(spp)
        } else {
            PixelSampler::independent(spp)
        }
    }
}

/// One tile's rows of the pass's film and of its work, each a slice of the tile's width.
type TileRows<'a> = (Vec<&'a mut [PixelSum]>, Vec<&'a mut [PixelWork]>);

/// The rows of each tile (in `tiles`' order, by their corners) of a row-major buffer `w`
/// wide: disjoint slices, so the tiles fill the buffer in parallel. An empty buffer (work a
/// pass does not record) gives every tile no rows.
fn tile_rows<'a, T>(
    buffer: &'a mut [T],
    w: usize,
    tiles: &[(usize, usize)],
) -> Vec<Vec<&'a mut [T]>> {
    if buffer.is_empty() {
        return tiles.iter().map(|_| Vec::new()).collect();
    }
    let columns = w.div_ceil(TILE);
    // Which of `tiles` each tile of the grid is (tiles outside a window are absent).
    let mut slot = vec![usize::MAX; columns * (buffer.len() / w.max(1)).div_ceil(TILE)];
    for (k, &(x0, y0)) in tiles.iter().enumerate() {
        slot[y0 / TILE * columns + x0 / TILE] = k;
    }
    let mut rows: Vec<Vec<&mut [T]>> = tiles.iter().map(|_| Vec::with_capacity(TILE)).collect();
    for (y, row) in buffer.chunks_mut(w.max(1)).enumerate() {
        for (tx, part) in row.chunks_mut(TILE).enumerate() {
            if let Some(tile) = rows.get_mut(slot[y / TILE * columns + tx]) {
                tile.push(part);
            }
        }
    }
    rows
}

/// The pass's two integrators: the render's own, and one with a fixed number of shadow rays
/// per area light (the adaptive pilot's, or one for one-ray pixels), with the batch's
/// photons.
fn pass_integrators<'s>(
    scene: &'s PreparedScene,
    options: &RenderOptions,
    plan: &SamplePlan,
    photons: Option<&PhotonBatch<'s>>,
) -> (Integrator<'s>, Integrator<'s>) {
    let fixed = match plan {
        SamplePlan::Uniform {
            fixed_light: Some(k),
            ..
        } => *k,
        _ => 1,
    };
    let fixed_options = RenderOptions {
        light_samples: LightSamples::Fixed(fixed),
        ..options.clone()
    };
    let (mut own, mut fixed) = (
        Integrator::new(scene, options),
        Integrator::new(scene, &fixed_options),
    );
    if let Some(p) = photons {
        own = own.with_photons(p.maps);
        fixed = fixed.with_photons(p.maps);
    }
    // A per-pixel plan shades only its one-ray pixels with the fixed integrator.
    if matches!(plan, SamplePlan::PerPixel { .. }) {
        fixed = fixed.one_ray();
    }
    (own, fixed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shares_that_tile_the_samples_tile_every_pixels_count() {
        let mut next = crate::geometry::uniform_stream(11);
        for _ in 0..2000 {
            let spp = 1 + (next() * 300.0) as u32;
            // Cut 0..spp at a few random places.
            let mut cuts: Vec<u32> = (0..1 + (next() * 5.0) as usize)
                .map(|_| (next() * f64::from(spp + 1)) as u32)
                .chain([0, spp])
                .collect();
            cuts.sort_unstable();
            let count = (next() * 5000.0) as u32;
            let parts: Vec<Range<u32>> = cuts
                .windows(2)
                .map(|c| {
                    Share {
                        range: c[0]..c[1],
                        spp,
                    }
                    .of(count)
                })
                .collect();
            assert_eq!(parts.first().map(|p| p.start), Some(0));
            assert_eq!(parts.last().map(|p| p.end), Some(count));
            assert!(
                parts.windows(2).all(|p| p[0].end == p[1].start),
                "{parts:?}"
            );
        }
        assert_eq!(Share::ALL.of(37), 0..37);
    }

    #[test]
    fn window_sums_add_the_square_around_and_stop_at_the_borders() {
        let (w, h) = (9, 7);
        let mut values = vec![0u32; w * h];
        values[2 * w + 1] = 1;
        values[6 * w + 8] = 5;
        let sums = window_sums(&values, w, 2);
        for y in 0..h {
            for x in 0..w {
                let near_first = x <= 3 && y <= 4;
                let near_second = x >= 6 && y >= 4;
                let expect = u32::from(near_first) + 5 * u32::from(near_second);
                assert_eq!(sums[y * w + x], expect, "({x}, {y})");
            }
        }
        assert_eq!(window_sums(&values, w, 0), values);
    }

    #[test]
    fn a_pilot_sample_that_stays_is_the_first_of_its_pixels_positions() {
        let options = RenderOptions {
            seed: 77,
            ..RenderOptions::default()
        };
        let pilot = pilot_plan(&options).pixel(1);
        assert_eq!(pilot.range, 0..1);
        let at = |seed, first| PositionPlan { seed, first };
        assert_eq!(pilot.position, at(77, 0));
        // Pixel 0 is near a penumbra (its pilot left out), pixel 1 not, pixel 2 on the
        // frame (its pilot's value judged it).
        let plan = SamplePlan::PerPixel {
            counts: &[6, 5, 4],
            seed: options.seed,
            one_ray: &[false, true, true],
            share: Share {
                range: 0..8,
                spp: 8,
            },
            resume_at: &[],
            positions: Positions {
                seed: options.seed,
                first: FirstPoints::AfterPilot(&[
                    PilotSample::LeftOut,
                    PilotSample::Stays,
                    PilotSample::Judged,
                ]),
            },
            control: None,
        };
        let (near, far) = (plan.pixel(0), plan.pixel(1));
        assert_eq!((near.range, near.position), (0..6, at(77, 0)));
        // Samples 0 to 4 take points 1 to 5, after the pilot's.
        assert_eq!((far.range, far.position), (0..5, at(77, 1)));
        // A sequence independent of the pilot's, from its point 0.
        let judged = plan.pixel(2);
        assert_eq!(
            (judged.range, judged.position),
            (0..4, at(77 ^ JUDGED_POSITIONS, 0))
        );
    }

    /// A pixel as the pilot leaves it; its pilot sample stays where `one_ray`.
    fn pixel(change: f64, cost: f64, one_ray: bool) -> AdaptivePixel {
        AdaptivePixel {
            change,
            cost,
            one_ray,
            pilot: if one_ray {
                PilotSample::Stays
            } else {
                PilotSample::LeftOut
            },
        }
    }

    /// Three one-ray pixels of changes 0, 1, 1 and costs 2, 2, 8, and one near a penumbra.
    fn four_pixels() -> [AdaptivePixel; 4] {
        [
            pixel(0.0, 2.0, true),
            pixel(1.0, 2.0, true),
            pixel(1.0, 8.0, true),
            pixel(5.0, 2.0, false),
        ]
    }

    #[test]
    fn pixels_share_their_time_by_change_over_the_root_of_cost() {
        let pixels = four_pixels();
        let counts = allocate(&pixels, 13.0, 4);
        // Each takes a quarter of the budget (3), and they share the time of the rest at
        // their costs, 9 more each for the one-ray pixels (whose pilot sample stays) and 10
        // for the one near a penumbra (whose pilot is left out), 128 in all, so that the
        // samples each pixel holds beyond its floor, its pilot sample among them where it
        // stays, go as change / sqrt(cost): weights 0, 1/sqrt(2), 1/sqrt(8), 5/sqrt(2),
        // 8.625, 4.3125 and 43.125 samples at t = 12.2 (7.625, 3.3125 and 43.125 more,
        // 128 in time), rounded.
        assert_eq!(counts, vec![3, 3 + 8, 3 + 3, 3 + 43]);
        let time: f64 = counts
            .iter()
            .zip(&pixels)
            .map(|(&n, p)| f64::from(n) * p.cost)
            .sum();
        // Within the rounding of each pixel's count (half a sample at its cost).
        let budget = 12.0 * 12.0 + 13.0 * 2.0;
        assert!((time - budget).abs() <= 7.0, "{time}");
        // No change anywhere: every pixel takes the budget's count, less the pilot where
        // it stays.
        let quiet = [pixel(0.0, 1.0, true), pixel(0.0, 3.0, false)];
        assert_eq!(allocate(&quiet, 8.0, 4), vec![7, 8]);
        // One sample: a pixel near a penumbra still takes one of its own, unless its pilot
        // sample stays (under adaptive area lights).
        assert_eq!(allocate(&pixels, 1.0, 4), vec![0, 0, 0, 1]);
        let kept = AdaptivePixel {
            pilot: PilotSample::Stays,
            ..pixel(5.0, 2.0, false)
        };
        assert_eq!(allocate(&[kept], 1.0, 4), vec![0]);
    }

    /// POV-Ray's stop for 16, 19 and 37 lens samples, on either side of each measured
    /// threshold: with its first lens cell seeing a brightness c and the rest black, a
    /// sample takes as many rays as POV-Ray's pixel does, and is their mean; two cells among
    /// the first seven stop it below c = 0.0339 at 16 samples (not at the one cell's 0.0437:
    /// the rule tests a variance, not a range), one channel as the three.
    #[test]
    fn the_lens_rule_stops_where_povray_does() {
        let scene = |settings: &str| {
            let src = format!(
                "camera {{ location <0, 0, -5> look_at 0 aperture 1 focal_point 0 {settings} }}"
            );
            let loaded = crate::lang::load_scene_source("t.pov", &src, &Default::default());
            PreparedScene::new(&loaded.expect("scene loads").scene)
        };
        let taken = |scene: &PreparedScene, seen: &[DVec3]| {
            let rule = camera::lens_rule(&scene.camera).expect("a measured count");
            let layout = scene.dimension_layout();
            let mut rays = 0;
            let mut sampler = PixelSampler::new(4);
            sampler.start(3, 2, 1, 99);
            let pixel = (3, 2, 8, 8);
            let mean = povray_lens_sample(scene, &layout, rule, pixel, &mut sampler, |_, _| {
                rays += 1;
                seen.get(rays - 1).copied().unwrap_or(DVec3::ZERO)
            });
            (rays, mean)
        };
        // One cell's brightness c at a threshold, and the rays taken below and above it.
        type Threshold = (f64, usize, usize);
        let measured: [(u32, &[Threshold]); 3] = [
            (
                16,
                &[(0.043668, 7, 11), (0.093297, 11, 15), (0.155196, 15, 16)],
            ),
            (19, &[(0.038926, 7, 13), (0.109414, 13, 19)]),
            (
                37,
                &[
                    (0.025332, 7, 13),
                    (0.071284, 13, 19),
                    (0.132139, 19, 23),
                    (0.179639, 23, 27),
                    (0.229170, 27, 31),
                    (0.287471, 31, 35),
                    (0.349131, 35, 37),
                ],
            ),
        ];
        for (count, thresholds) in measured {
            let scene = scene(&format!("blur_samples {count}"));
            for &(c, below, above) in thresholds {
                for (c, n) in [(c * 0.999, below), (c * 1.001, above)] {
                    let (rays, mean) = taken(&scene, &[DVec3::splat(c)]);
                    assert_eq!(rays, n, "{count} samples, c = {c}");
                    assert!((mean - DVec3::splat(c / n as f64)).abs().max_element() < 1e-15);
                    let green = taken(&scene, &[DVec3::new(0.0, c, 0.0)]).0;
                    assert_eq!(green, n, "{count} samples, green alone, c = {c}");
                }
            }
            // Where every cell agrees, the first seven decide.
            assert_eq!(
                taken(&scene, &[DVec3::splat(0.5); 37]),
                (7, DVec3::splat(0.5))
            );
        }
        let sixteen = scene("blur_samples 16");
        let two = |c: f64| taken(&sixteen, &[DVec3::splat(c), DVec3::ZERO, DVec3::splat(c)]).0;
        assert_eq!((two(0.0335), two(0.0345)), (7, 11));
        // A written variance scales the thresholds (measured at 1/128: one hit stops at 7
        // below c = 0.3859-0.3867); confidence 0.9 written is the default.
        let written = scene("blur_samples 16 variance 1/128 confidence 0.9");
        let c = 0.043668 * (1.0 / 128.0 / 1e-4f64).sqrt();
        assert_eq!(taken(&written, &[DVec3::splat(c * 0.999)]).0, 7);
        assert_eq!(taken(&written, &[DVec3::splat(c * 1.001)]).0, 11);
        // Seven samples never stop early; another confidence or a minimum count: no rule
        // measured.
        let unmeasured = [
            "blur_samples 7",
            "blur_samples 16 confidence 0.5",
            "blur_samples 4, 16",
        ];
        for settings in unmeasured {
            assert_eq!(
                camera::lens_rule(&scene(settings).camera),
                None,
                "{settings}"
            );
        }
    }

    /// A scene's hidden noise, each kind in a scene of its own, keeps a quarter of the
    /// samples in every pixel; a plain scene, area light shadows included, an eighth.
    #[test]
    fn only_hidden_noise_keeps_the_quarter_floor() {
        let share = |camera: &str, light: &str, extra: &str| {
            let src = format!(
                "camera {{ location <0, 1, -5> look_at 0 {camera} }}
                 light_source {{ <0, 5, -5> rgb 1 area_light x, z, 3, 3 {light} }}
                 sphere {{ 0, 1 pigment {{ rgb 1 }} }} {extra}"
            );
            let loaded = crate::lang::load_scene_source("t.pov", &src, &Default::default());
            let scene = PreparedScene::new(&loaded.expect("scene loads").scene);
            AdaptiveScene::of(&scene, &RenderOptions::default()).floor_share
        };
        assert_eq!(share("", "", ""), PLAIN_FLOOR_SHARE);
        let lens = "aperture 0.5 focal_point 0 blur_samples 4";
        assert_eq!(share(lens, "", ""), FLOOR_SHARE);
        let measured = "aperture 0.5 focal_point 0 blur_samples 16";
        assert_eq!(share(measured, "", ""), PLAIN_FLOOR_SHARE);
        let written = "aperture 0.5 focal_point 0 blur_samples 16 confidence 0.5";
        assert_eq!(share(written, "", ""), FLOOR_SHARE);
        assert_eq!(share("", "jitter", ""), FLOOR_SHARE);
        assert_eq!(
            share("", "", "media { scattering { 1, 0.1 } }"),
            FLOOR_SHARE
        );
        // An eighth of 16 spp where the change is nowhere but one pixel: the floor itself.
        let pixels = [pixel(0.0, 1.0, true), pixel(1.0, 1.0, true)];
        assert_eq!(allocate(&pixels, 16.0, PLAIN_FLOOR_SHARE)[0], 2);
        assert_eq!(allocate(&pixels, 16.0, FLOOR_SHARE)[0], 4);
    }

    /// The water level spends the time it is given: over 10,000 pixels of random change
    /// and cost, a third with no change and half with their pilot sample kept, the
    /// unrounded shares max(0, t w - held) cost the time to a millionth, for budgets from
    /// a tenth of a sample a pixel to 64, and a level 0.1% lower spends less.
    #[test]
    fn the_water_level_spends_the_time() {
        let mut next = crate::geometry::uniform_stream(5);
        let pixels: Vec<AdaptivePixel> = (0..10_000)
            .map(|_| {
                let change = if next() < 0.33 { 0.0 } else { next() * next() };
                pixel(change, 1.0 + 4.0 * next(), next() < 0.5)
            })
            .collect();
        let spent: f64 = pixels.iter().map(|p| p.change * p.cost.sqrt()).sum();
        let time_at = |t: f64| -> f64 {
            let more = |p: &AdaptivePixel| {
                let held = f64::from(u8::from(p.keeps_pilot()));
                (t * p.change / p.cost.sqrt() - held).max(0.0)
            };
            pixels.iter().map(|p| p.cost * more(p)).sum()
        };
        for per_pixel in [0.1, 0.5, 1.0, 4.0, 64.0] {
            let time = per_pixel * pixels.len() as f64;
            let t = water_level(&pixels, time, spent);
            let error = (time_at(t) - time).abs() / time;
            assert!(error < 1e-6, "{per_pixel}: relative error {error}");
            assert!(time_at(t * 0.999) < time);
        }
    }

    /// A fractional average shares the time its fraction buys as a whole count does: at
    /// 1.6 samples per pixel the four pixels' time beyond their floors (0, 0, 0 and 1) is
    /// 0.6 of a sample each, 8.4 in all, and the pixels whose pilot stays hold one sample
    /// each already: the one near a penumbra takes all of it (4.2 samples, rounded), the
    /// others' share falling short of their pilot's; each pixel's count lies between those
    /// of the whole counts around the average.
    #[test]
    fn a_fractional_average_spends_its_fraction_where_the_change_is() {
        let pixels = four_pixels();
        let (one, half, two) = (
            allocate(&pixels, 1.0, 4),
            allocate(&pixels, 1.6, 4),
            allocate(&pixels, 2.0, 4),
        );
        assert_eq!(half, vec![0, 0, 0, 5]);
        assert_eq!(two, vec![0, 0, 0, 8]);
        for i in 0..pixels.len() {
            assert!(
                one[i] <= half[i] && half[i] <= two[i],
                "{one:?} {half:?} {two:?}"
            );
        }
        // 2.5: floors 0 (a quarter of 3, rounded down) and 1 near the penumbra; 1.5 more
        // a pixel, 21 in all: 0.92 more where the pilot stays and change / sqrt(cost) is
        // 1/sqrt(2) (1.92 in all), 9.58 near the penumbra, none where it is 1/sqrt(8).
        assert_eq!(allocate(&pixels, 2.5, 4), vec![0, 1, 0, 11]);
    }

    /// An average that is not whole is for adaptive renders, above 1, rounding up to the
    /// render's `samples_per_pixel`.
    #[test]
    fn a_fractional_average_is_checked() {
        assert!(check_average(1.5, 2, true).is_ok());
        assert!(check_average(1.5, 2, false).is_err());
        assert!(check_average(1.5, 3, true).is_err());
        assert!(check_average(0.5, 1, true).is_err());
        assert!(check_average(1.0, 1, true).is_err());
    }
}
