//! Rendering: the sampler, the integrator, lights, the film, and the one loop that owns
//! tiles, threads and progress.

pub mod camera;
pub mod dimensions;
pub mod film;
pub mod fog;
pub mod integrator;
pub mod lights;
pub mod media;
pub mod mesh_camera;
pub mod photons;
pub mod prepared;
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
    let run = |plan: &SamplePlan, progress: &dyn Progress| match &pool {
        Some(pool) => pool.install(|| render_pass(scene, options, plan, progress)),
        None => render_pass(scene, options, plan, progress),
    };
    let (film, rays, samples) = if let Some(target) = &options.target_error {
        target::render_to_error(options, target, &|plan, p| run(plan, p), progress)
    } else if options.adaptive {
        adaptive_passes(
            options,
            options.samples_per_pixel.max(1),
            &|plan, p| run(plan, p),
            progress,
        )
    } else {
        uniform_passes(
            options,
            range.clone(),
            checkpoint,
            &|plan, p| run(plan, p),
            progress,
        )
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
    if (options.adaptive || options.target_error.is_some()) && options.sample_range.is_some() {
        return Err(RenderError(
            "adaptive sampling and --target-error cannot be split into sample ranges".into(),
        ));
    }
    Ok(range)
}

fn check_checkpoint(options: &RenderOptions, done: &Film) -> Result<(), RenderError> {
    if options.adaptive || options.target_error.is_some() {
        return Err(RenderError(
            "adaptive and target-error renders cannot resume from a checkpoint".into(),
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
    // Without a checkpoint the first pass's film becomes the render's: merged into an empty
    // film it would be the same, at the cost of a second film (96 bytes a pixel).
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
            one_ray: false,
        };
        let (mut part, pass_rays) = run(&plan, progress);
        let film = match &mut film {
            Some(f) => {
                f.merge(&part);
                f
            }
            None => {
                // As `merge` leaves it.
                part.non_finite.sort_unstable_by_key(|&(x, y)| (y, x));
                film.insert(part)
            }
        };
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

/// Pixels rendered: the window's, or the whole image's.
fn pixel_count(options: &RenderOptions) -> u64 {
    match &options.window {
        Some(win) => (win.x.len() * win.y.len()) as u64,
        None => (options.width * options.height) as u64,
    }
}

/// Samples per pixel of the adaptive pilot pass.
const ADAPTIVE_PILOT: u32 = 4;

/// A render pass, as `render` runs it on its thread pool.
type Pass<'a> = dyn Fn(&SamplePlan, &dyn Progress) -> (Film, RayCounts) + 'a;

/// Adaptive sampling in two passes. A pilot of a few samples per pixel measures the noise;
/// each pixel's further samples then follow the noise its neighbours showed, not its own,
/// so its sample count does not depend on its own samples and the pilot's samples can be
/// kept in its mean without bias (a pixel's own noise deciding its count would bias it).
fn adaptive_passes(
    options: &RenderOptions,
    spp: u32,
    run: &Pass,
    progress: &dyn Progress,
) -> (Film, RayCounts, u64) {
    let pilot_spp = ADAPTIVE_PILOT.min(spp);
    let pilot = SamplePlan::Uniform {
        spp: pilot_spp,
        range: 0..pilot_spp,
        first: 0,
        checkpoint: None,
        seed: options.seed ^ 0xad47_1be5_5eed_0001,
        one_ray: true,
    };
    let (mut film, mut rays) = run(&pilot, &());
    let noise = neighbour_noise(&film);
    let counts = allocate(&noise, pilot_spp, spp);
    let extra: u64 = counts.iter().map(|&n| n as u64).sum();
    // Where the neighbours showed no noise at all, the light is seen whole or not at all
    // there: one shadow ray per sample is exact, and covering the grid would be wasted.
    let one_ray: Vec<bool> = noise.iter().map(|&s| s == 0.0).collect();
    let plan = SamplePlan::PerPixel {
        counts,
        seed: options.seed,
        one_ray,
    };
    let (more, more_rays) = run(&plan, progress);
    // The pilot's one-ray samples stay in a pixel's mean only where its further samples
    // are of the same kind: beside samples that cover the light grid they would only add
    // their noise. (Which it is depends on the neighbours alone, so either mean is unbiased.)
    let SamplePlan::PerPixel {
        counts, one_ray, ..
    } = &plan
    else {
        unreachable!("the plan above is per pixel")
    };
    let w = options.width;
    let outside = |i: usize| {
        let win = options.window.as_ref();
        win.is_some_and(|win| !win.contains(i % w, i / w))
    };
    for (i, (pixel, extra)) in film.pixels.iter_mut().zip(&more.pixels).enumerate() {
        if outside(i) {
            // The pilot covered the whole image, for the allocation; the window alone shows.
            *pixel = PixelSum::default();
        } else if one_ray[i] || counts[i] == 0 {
            pixel.merge(extra);
        } else {
            *pixel = *extra;
        }
    }
    film.non_finite
        .retain(|&(x, y)| !outside(y as usize * w + x as usize));
    film.non_finite.extend_from_slice(&more.non_finite);
    rays.add(&more_rays);
    (film, rays, extra + pixel_count(options) * pilot_spp as u64)
}

/// Which samples each pixel takes.
enum SamplePlan<'a> {
    /// Every pixel takes samples `range` of `spp`, except those a checkpoint holds (its
    /// count of them from `first` on); with `one_ray`, one shadow ray per area light per
    /// sample whatever the render's light sampling.
    Uniform {
        spp: u32,
        range: Range<u32>,
        first: u32,
        checkpoint: Option<&'a Film>,
        seed: u64,
        one_ray: bool,
    },
    /// Adaptive sampling: pixel i takes counts[i] samples (all of its own strata; none
    /// where the count is 0), with one shadow ray per light per sample where one_ray[i].
    PerPixel {
        counts: Vec<u32>,
        seed: u64,
        one_ray: Vec<bool>,
    },
}

/// One pixel's part of a plan.
struct PixelPlan {
    spp: u32,
    range: Range<u32>,
    seed: u64,
    one_ray: bool,
}

impl SamplePlan<'_> {
    /// The sample indices some pixel of the plan takes (a superset).
    fn index_span(&self) -> Range<u32> {
        match self {
            SamplePlan::Uniform { range, .. } => range.clone(),
            SamplePlan::PerPixel { counts, .. } => 0..counts.iter().copied().max().unwrap_or(0),
        }
    }

    fn seed(&self) -> u64 {
        match self {
            SamplePlan::Uniform { seed, .. } | SamplePlan::PerPixel { seed, .. } => *seed,
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
                one_ray,
            } => {
                let done = checkpoint.map_or(0, |c| c.pixels[i].count);
                PixelPlan {
                    spp: *spp,
                    range: range.start.max(first + done)..range.end,
                    seed: *seed,
                    one_ray: *one_ray,
                }
            }
            SamplePlan::PerPixel {
                counts,
                seed,
                one_ray,
            } => PixelPlan {
                spp: counts[i].max(1),
                range: 0..counts[i],
                seed: *seed,
                one_ray: one_ray[i],
            },
        }
    }
}

/// The noise around each pixel after a pilot of `pilot_spp` samples: the largest pilot
/// deviation among its eight neighbours. A pilot of a few samples can miss noise that is
/// there (four light samples that happen to agree), hence the neighbourhood; the pixel
/// itself is left out so that what is decided from this does not depend on its own samples.
fn neighbour_noise(pilot: &Film) -> Vec<f64> {
    let (w, h) = (pilot.width, pilot.height);
    let sigma: Vec<f64> = pilot.pixels.iter().map(sample_deviation).collect();
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let mut m = 0.0f64;
            for yy in y.saturating_sub(1)..(y + 2).min(h) {
                for xx in x.saturating_sub(1)..(x + 2).min(w) {
                    if (xx, yy) != (x, y) {
                        m = m.max(sigma[yy * w + xx]);
                    }
                }
            }
            m
        })
        .collect()
}

/// The standard deviation of one sample of the pixel, over the three channels (0 with fewer
/// than two samples).
fn sample_deviation(p: &PixelSum) -> f64 {
    let v = p.variance_of_mean();
    (f64::from(p.count) * (v[0] + v[1] + v[2]) / 3.0).sqrt()
}

/// The samples each pixel takes after the pilot, for `spp` per pixel on average in all, in
/// proportion to the noise around it (which minimises the summed variance for a fixed
/// budget).
fn allocate(noise: &[f64], pilot_spp: u32, spp: u32) -> Vec<u32> {
    let pixels = noise.len() as f64;
    let spare = (spp - pilot_spp) as f64 * pixels;
    let total: f64 = noise.iter().sum();
    noise
        .iter()
        .map(|s| {
            let extra = if total > 0.0 {
                spare * s / total
            } else {
                spare / pixels
            };
            extra.round() as u32
        })
        .collect()
}

/// The camera ray of the sample `sampler` has started, for pixel (x, y) of a w x h image.
fn sample_camera_ray(
    scene: &PreparedScene,
    layout: &dimensions::DimensionLayout,
    (x, y, w, h): (usize, usize, usize, usize),
    sampler: &mut PixelSampler,
) -> Option<Ray> {
    sampler.set_dimension(layout.dimension(0, Purpose::PixelPosition));
    let (u, v) = sampler.get_2d();
    if let Some(mesh) = &scene.mesh_camera {
        return mesh.ray((x, y, w, h), (u, v));
    }
    let sx = (x as f64 + u) / w as f64 - 0.5;
    let sy = 0.5 - (y as f64 + v) / h as f64;
    sampler.set_dimension(layout.dimension(0, Purpose::Lens));
    let lens = sampler.get_2d();
    camera_ray(&scene.camera, sx, sy, lens)
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
) -> (Film, RayCounts) {
    let shooter = Integrator::new(scene, options);
    let first_radius = scene
        .settings
        .photons
        .filter(|_| !scene.world.photon_targets().is_empty())
        .and_then(|_| {
            photons::first_radius(&shooter.shoot_photons(0, RADIUS_SEED, PHOTONS_PER_PASS))
        });
    let Some(first_radius) = first_radius else {
        return render_indices(scene, options, plan, None, progress);
    };
    let span = plan.index_span();
    let batches: Vec<Range<u32>> = span
        .clone()
        .step_by(PHOTON_BATCH as usize)
        .map(|a| a..(a + PHOTON_BATCH).min(span.end))
        .collect();
    let mut film = Film::new(options.width, options.height);
    let mut rays = RayCounts::default();
    for (i, batch) in batches.iter().enumerate() {
        let maps = photons::PhotonMaps {
            first: batch.start,
            maps: batch
                .clone()
                .into_par_iter()
                .map(|pass| {
                    let shot = shooter.shoot_photons(pass, plan.seed(), PHOTONS_PER_PASS);
                    photons::PhotonMap::new(shot, photons::pass_radius(first_radius, pass))
                })
                .collect(),
        };
        let photons = PhotonBatch {
            maps: &maps,
            indices: batch.clone(),
            number: (i as u64, batches.len() as u64),
        };
        let (part, part_rays) = render_indices(scene, options, plan, Some(&photons), progress);
        film.merge(&part);
        rays.add(&part_rays);
        if progress.cancelled() {
            break;
        }
    }
    (film, rays)
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
) -> (Film, RayCounts) {
    let (w, h) = (options.width, options.height);
    let window = match plan {
        // In adaptive mode the one uniform plan is the pilot.
        SamplePlan::Uniform { .. } if options.adaptive => None,
        _ => options.window.clone(),
    };
    let inside = |x: usize, y: usize| window.as_ref().is_none_or(|win| win.contains(x, y));
    let tiles: Vec<(usize, usize)> = (0..h.div_ceil(TILE))
        .flat_map(|ty| (0..w.div_ceil(TILE)).map(move |tx| (tx * TILE, ty * TILE)))
        .filter(|&(x0, y0)| {
            window.as_ref().is_none_or(|win| {
                x0 < win.x.end
                    && win.x.start < x0 + TILE
                    && y0 < win.y.end
                    && win.y.start < y0 + TILE
            })
        })
        .collect();
    let (batch, batches) = photons.map_or((0, 1), |p| p.number);
    let total = tiles.len() as u64 * batches;
    let done = AtomicU64::new(tiles.len() as u64 * batch);
    let one_ray_options = RenderOptions {
        light_samples: LightSamples::Fixed(1),
        ..options.clone()
    };
    let (mut integrator, mut one_ray_integrator) = (
        Integrator::new(scene, options),
        Integrator::new(scene, &one_ray_options),
    );
    if let Some(p) = photons {
        integrator = integrator.with_photons(p.maps);
        one_ray_integrator = one_ray_integrator.with_photons(p.maps);
    }
    let layout = *integrator.layout();
    let new_sampler = |spp: u32| {
        if options.stratified {
            PixelSampler::new(spp)
        } else {
            PixelSampler::independent(spp)
        }
    };
    let render_tile = |&(x0, y0): &(usize, usize)| {
        let mut sampler = new_sampler(1);
        let mut counts = RayCounts::default();
        let mut sums = Vec::with_capacity(TILE * TILE);
        let mut non_finite = Vec::new();
        for y in y0..(y0 + TILE).min(h) {
            for x in x0..(x0 + TILE).min(w) {
                let PixelPlan {
                    spp,
                    range,
                    seed,
                    one_ray,
                } = plan.pixel(y * w + x);
                let range = match photons {
                    Some(p) => range.start.max(p.indices.start)..range.end.min(p.indices.end),
                    None => range,
                };
                if !inside(x, y) {
                    sums.push(PixelSum::default());
                    continue;
                }
                if sampler.samples_per_pixel() != spp {
                    sampler = new_sampler(spp);
                }
                let integrator = if one_ray {
                    &one_ray_integrator
                } else {
                    &integrator
                };
                let mut sum = PixelSum::default();
                for index in range {
                    if progress.cancelled() {
                        break;
                    }
                    sampler.start(x as u32, y as u32, index, seed);
                    // No ray (outside a fisheye's circle): black, as POV-Ray renders it.
                    let l = sample_camera_ray(scene, &layout, (x, y, w, h), &mut sampler)
                        .map_or(DVec3::ZERO, |ray| {
                            integrator.radiance(&ray, &mut sampler, &mut counts)
                        });
                    if l.is_finite() {
                        sum.add(l.to_array());
                    } else {
                        sum.add([0.0; 3]);
                        non_finite.push((x as u32, y as u32));
                    }
                }
                sums.push(sum);
            }
        }
        let n = done.fetch_add(1, Ordering::Relaxed) + 1;
        progress.advance(n, total);
        (sums, counts, non_finite)
    };
    let results: Vec<_> = tiles.par_iter().map(render_tile).collect();
    let mut film = Film::new(w, h);
    let mut rays = RayCounts::default();
    for (&(x0, y0), (sums, counts, non_finite)) in tiles.iter().zip(results) {
        let tw = (x0 + TILE).min(w) - x0;
        for (i, s) in sums.into_iter().enumerate() {
            film.pixels[(y0 + i / tw) * w + x0 + i % tw] = s;
        }
        rays.add(&counts);
        film.non_finite.extend(non_finite);
    }
    (film, rays)
}
