//! Rendering to a target error: passes of samples until the estimated RMSE of the image
//! (its noise, from each pixel's sample variance) is below the target with 95% confidence.
//!
//! Each pass after the first sends its samples where the noise is, in proportion to the
//! noise *around* each pixel (its eight neighbours, not itself), so a pixel's sample count
//! never depends on its own samples and its mean stays unbiased. Only the decision to stop
//! depends on every pixel, the pixel itself among them, through one image-wide sum: its
//! influence on any one pixel is of order 1/pixels (measured in tests/farm.rs and the
//! note, as the bias test against POV-Ray still passing).
//!
//! A pass's samples take other values than the passes' before (a seed of their own), but
//! their pixel positions continue each pixel's sequence of the first pass, so all of a
//! pixel's positions are one stratified set. The stop rule's variance treats the samples
//! as independent, so this shows in the image, not in the count: 640x480, target 0.003,
//! the same samples, RMSE against POV-Ray's k = 8 reference pattern_gradient 0.00136 ->
//! 0.00120, checker 0.00135 -> 0.00131, glass 0.00296 -> 0.00289 (before, each pass
//! drew positions of its own).

use super::{
    Film, FirstPoints, Pass, Positions, Progress, RayCounts, RenderOptions, SamplePlan, Share,
    neighbour_noise,
};

/// What `--target-error` asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TargetError {
    /// The RMSE over pixels and channels, in linear units, or relative to the image's mean.
    pub value: f64,
    pub relative: bool,
    /// Samples per pixel on average at most: a target the scene cannot reach ends here.
    pub max_spp: u32,
}

/// Samples per pixel of the first pass: enough for a first variance estimate per pixel.
pub const FIRST_PASS: u32 = 16;

/// One-sided 95% normal quantile: the stop rule asks the upper bound of the estimate.
const Z95: f64 = 1.6449;

/// The noise estimate of a film.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoiseEstimate {
    /// Mean over pixels and channels of the variance of each pixel's mean.
    pub mse: f64,
    /// Its standard error (from each pixel's variance estimate, as for normal samples).
    pub standard_error: f64,
    /// The image's mean value over pixels and channels.
    pub mean: f64,
}

impl NoiseEstimate {
    pub fn of(film: &Film) -> NoiseEstimate {
        let (mut mse, mut var_of_mse, mut mean) = (0.0, 0.0, 0.0);
        for p in &film.pixels {
            let v = p.variance_of_mean();
            let vi = (v[0] + v[1] + v[2]) / 3.0;
            mse += vi;
            if p.count > 1 {
                var_of_mse += 2.0 * vi * vi / f64::from(p.count - 1);
            }
            let m = p.mean();
            mean += (m[0] + m[1] + m[2]) / 3.0;
        }
        let n = film.pixels.len().max(1) as f64;
        NoiseEstimate {
            mse: mse / n,
            standard_error: var_of_mse.sqrt() / n,
            mean: mean / n,
        }
    }

    /// The RMSE the estimate bounds from above with 95% confidence.
    pub fn upper_rmse(&self) -> f64 {
        (self.mse + Z95 * self.standard_error).max(0.0).sqrt()
    }
}

impl TargetError {
    /// The target in linear units for a film whose mean is `mean`.
    fn absolute(&self, mean: f64) -> f64 {
        if self.relative {
            self.value * mean
        } else {
            self.value
        }
    }
}

/// Passes until the target or the sample cap: the film, the rays and the samples taken.
pub(super) fn render_to_error(
    options: &RenderOptions,
    target: &TargetError,
    run: &Pass,
    progress: &dyn Progress,
) -> (Film, RayCounts, u64) {
    let first_seed = pass_seed(options.seed, 0);
    let first = SamplePlan::Uniform {
        spp: FIRST_PASS,
        range: 0..FIRST_PASS,
        first: 0,
        checkpoint: None,
        seed: first_seed,
        position_seed: first_seed,
        fixed_light: None,
    };
    let super::PassOutput {
        mut film, mut rays, ..
    } = run(&first, progress, None);
    let pixels = film.pixels.len() as u64;
    let cap = u64::from(target.max_spp.max(FIRST_PASS)) * pixels;
    for pass in 1.. {
        progress.pass(&film);
        let estimate = NoiseEstimate::of(&film);
        let goal = target.absolute(estimate.mean);
        let taken = film.samples();
        if progress.cancelled() || estimate.upper_rmse() <= goal || taken >= cap {
            break;
        }
        let budget = pass_budget(&estimate, goal, taken, pixels).min(cap - taken);
        let counts = allocate(&neighbour_noise(&film), budget);
        let one_ray = vec![false; film.pixels.len()];
        let taken: Vec<u32> = film.pixels.iter().map(|p| p.count).collect();
        let plan = SamplePlan::PerPixel {
            counts: &counts,
            seed: pass_seed(options.seed, pass),
            one_ray: &one_ray,
            share: Share::ALL,
            resume_at: &[],
            // Each pass's positions continue the pixel's sequence where the passes before
            // stopped: all of its samples are one stratified set.
            positions: Positions {
                seed: first_seed,
                first: FirstPoints::Listed(&taken),
            },
            control: None,
        };
        let more = run(&plan, progress, Some(film));
        film = more.film;
        rays.add(&more.rays);
    }
    let samples = film.samples();
    (film, rays, samples)
}

/// Samples for the next pass: what the 1/n law says the target needs, at most as many as
/// taken so far (so the estimate is checked again before the budget grows further) and at
/// least a quarter sample per pixel (so every pass moves).
fn pass_budget(estimate: &NoiseEstimate, goal: f64, taken: u64, pixels: u64) -> u64 {
    let upper = estimate.upper_rmse();
    let ratio = if goal > 0.0 {
        (upper / goal).powi(2)
    } else {
        f64::INFINITY
    };
    let needed = (taken as f64 * (ratio - 1.0)).ceil();
    (needed.min(taken as f64) as u64).max(pixels.div_ceil(4))
}

/// `budget` samples over the pixels in proportion to the noise around each (evenly where
/// there is none anywhere), rounded per pixel.
fn allocate(noise: &[f64], budget: u64) -> Vec<u32> {
    let total: f64 = noise.iter().sum();
    let n = noise.len() as f64;
    noise
        .iter()
        .map(|&s| {
            let share = if total > 0.0 { s / total } else { 1.0 / n };
            (budget as f64 * share).round() as u32
        })
        .collect()
}

/// Each pass draws its own stratified samples: a seed of its own.
fn pass_seed(seed: u64, pass: u32) -> u64 {
    seed ^ (0x7a59_e7e3_0000_0000 | u64::from(pass)).wrapping_mul(0x9e37_79b9_7f4a_7c15)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn film_of(samples: &[&[f64]]) -> Film {
        let mut film = Film::new(samples.len(), 1);
        for (p, s) in film.pixels.iter_mut().zip(samples) {
            s.iter().for_each(|&v| p.add([v; 3]));
        }
        film
    }

    #[test]
    fn the_estimate_is_the_mean_variance_of_the_pixel_means() {
        // Pixel 0: samples 0, 2 (variance 2, of the mean 1); pixel 1: 1, 1, 1 (0).
        let e = NoiseEstimate::of(&film_of(&[&[0.0, 2.0], &[1.0, 1.0, 1.0]]));
        assert!((e.mse - 0.5).abs() < 1e-12, "{e:?}");
        assert!((e.mean - 1.0).abs() < 1e-12);
        // 2 * 1^2 / (2 - 1) for pixel 0, over 2 pixels: sqrt(2) / 2.
        assert!((e.standard_error - 2f64.sqrt() / 2.0).abs() < 1e-12);
        assert!(e.upper_rmse() > e.mse.sqrt());
    }

    #[test]
    fn budgets_follow_the_inverse_law_within_their_bounds() {
        let e = NoiseEstimate {
            mse: 4e-4,
            standard_error: 0.0,
            mean: 0.5,
        };
        // RMSE 0.02 against 0.01: four times the samples, so three times more; capped at
        // as many as taken.
        assert_eq!(pass_budget(&e, 0.01, 1000, 10), 1000);
        // Against 0.018: (0.02 / 0.018)^2 - 1 = 0.2346 of 1000.
        assert_eq!(pass_budget(&e, 0.018, 1000, 10), 235);
        // Nearly there: still a quarter sample per pixel.
        assert_eq!(pass_budget(&e, 0.0199999, 1000, 100), 25);
    }

    #[test]
    fn allocation_follows_the_noise_and_spreads_evenly_without_it() {
        assert_eq!(allocate(&[0.0, 1.0, 3.0], 8), vec![0, 2, 6]);
        assert_eq!(allocate(&[0.0; 4], 8), vec![2; 4]);
    }

    /// Every pass after the first takes each pixel's positions from where the passes before
    /// stopped, in the first pass's sequences, so a pixel's samples are one stratified set.
    #[test]
    fn passes_continue_each_pixels_positions() {
        let options = RenderOptions {
            width: 4,
            height: 3,
            seed: 5,
            ..RenderOptions::default()
        };
        let target = TargetError {
            value: 1e-9,
            relative: false,
            max_spp: 64,
        };
        let seen = std::cell::RefCell::new(Vec::new());
        let run = |plan: &SamplePlan, _: &dyn Progress, film: Option<Film>| {
            let mut film = film.unwrap_or_else(|| Film::new(4, 3));
            for (i, p) in film.pixels.iter_mut().enumerate() {
                let pixel = plan.pixel(i);
                seen.borrow_mut()
                    .push((i, p.count, pixel.range.clone(), pixel.position));
                // Noisy samples, so that the target is never met.
                pixel
                    .range
                    .for_each(|k| p.add([f64::from(k % 2 + i as u32); 3]));
            }
            super::super::PassOutput {
                film,
                rays: RayCounts::default(),
                work: Vec::new(),
            }
        };
        let (film, _, _) = render_to_error(&options, &target, &run, &());
        let seen = seen.into_inner();
        assert!(seen.len() >= 3 * 12, "several passes: {}", seen.len());
        let first_seed = pass_seed(5, 0);
        for (i, before, range, position) in seen {
            assert_eq!(position.seed, first_seed);
            // The pass's sample k is point before + k: after the pixel's earlier samples.
            assert_eq!((range.start, position.first), (0, before), "pixel {i}");
        }
        assert!(film.samples() >= 64 * 12);
    }

    #[test]
    fn relative_targets_scale_with_the_image() {
        let t = TargetError {
            value: 0.01,
            relative: true,
            max_spp: 64,
        };
        assert!((t.absolute(0.5) - 0.005).abs() < 1e-15);
        let t = TargetError {
            relative: false,
            ..t
        };
        assert_eq!(t.absolute(0.5), 0.01);
    }
}
