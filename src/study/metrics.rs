//! Bias and noise of Monte Carlo replicates against a POV-Ray reference, exactly as
//! `testing-statistics.md` defines them. A noisy image cannot be judged with a per-pixel
//! threshold, so noise (from replicate differences) and bias (from products of independent
//! replicates' errors, which have expectation b^2 and no noise term) are estimated apart.
//!
//! All sums run in `f64`. Images whose size is not a multiple of the block or tile size get
//! partial blocks at the right and bottom edges, averaged over the pixels they hold. A
//! non-finite value makes every statistic it touches NaN, and the verdict fails and lists it.

use super::StudyError;
use crate::output::Image;
use std::fmt;

/// The "converges to POV-Ray" criterion: sqrt(B) at or below this passes.
pub const SQRT_B_THRESHOLD: f64 = 0.005;
/// Side of the blocks the bias is judged on: block means shrink the reference's own
/// quadrature error at edges to about 0.001.
pub const BIAS_BLOCK: usize = 4;
/// Side of the tiles of the tile test.
pub const TILE: usize = 8;
/// Sidak-corrected critical value: alpha = 1e-3 over about 600 tiles.
pub const Z_STAR: f64 = 4.78;
/// Absolute tile tolerance, for the half-float reference and shading round-off.
pub const TILE_ABS_TOLERANCE: f64 = 0.004;
/// Relative tile tolerance, times |tile mean of the reference|.
pub const TILE_REL_TOLERANCE: f64 = 0.02;
/// How many non-finite positions a verdict keeps (the count is always exact).
pub const MAX_NON_FINITE_LISTED: usize = 32;

/// The bias estimate on 4x4 block means. `b` may come out negative when the replicates are
/// closer to the reference than its own error bound; `sqrt_b` clamps that to 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bias {
    /// B = cross - reference_term.
    pub b: f64,
    /// Mean over blocks, channels and pairs a < b of (x_a - r)(x_b - r): estimates b^2.
    pub cross: f64,
    /// Mean over blocks and channels of (r_k - r_k/2)^2: the reference's own error.
    pub reference_term: f64,
}

impl Bias {
    /// The noise-free distance from POV-Ray.
    pub fn sqrt_b(&self) -> f64 {
        self.b.max(0.0).sqrt()
    }
}

/// One 8x8 tile and channel where the replicates' mean is further from the reference than
/// tolerance and noise allow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TileFailure {
    /// Tile column and row.
    pub tile_x: usize,
    pub tile_y: usize,
    /// Pixel at the tile's top-left corner.
    pub x: usize,
    pub y: usize,
    pub channel: usize,
    /// d_T = mean over the tile of (xbar - r).
    pub d: f64,
    /// delta_T + z* SE_T.
    pub threshold: f64,
    /// SE_T, for judging how far past the threshold d is.
    pub standard_error: f64,
    /// r_T, the tile mean of the reference.
    pub reference_mean: f64,
}

#[derive(Debug, Clone, PartialEq, Default)]
pub struct TileReport {
    /// Number of (tile, channel) pairs tested.
    pub tested: usize,
    /// Failing (tile, channel) pairs in row-major tile order.
    pub failures: Vec<TileFailure>,
}

impl TileReport {
    pub fn failed(&self) -> usize {
        self.failures.len()
    }
}

/// Which input image a non-finite value was found in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageRole {
    Replicate(usize),
    Reference,
    HalfReference,
}

impl fmt::Display for ImageRole {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImageRole::Replicate(k) => write!(f, "replicate {k}"),
            ImageRole::Reference => write!(f, "reference"),
            ImageRole::HalfReference => write!(f, "half reference"),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NonFinite {
    pub image: ImageRole,
    pub x: usize,
    pub y: usize,
    pub channel: usize,
}

/// Pixel-wise differences between two images, for charts against wall time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImageDifference {
    pub rmse: f64,
    pub mean_abs: f64,
    pub max_abs: f64,
    /// (x, y, channel) of the largest absolute difference.
    pub max_at: (usize, usize, usize),
}

/// Everything a "converges to POV-Ray" test decides on, in one value.
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    pub replicates: usize,
    pub width: usize,
    pub height: usize,
    pub bias: Bias,
    /// sqrt(max(B, 0)).
    pub sqrt_b: f64,
    /// sqrt(V): the per-pixel noise of one replicate.
    pub sqrt_v: f64,
    pub tiles: TileReport,
    /// Exact count of non-finite values over all inputs.
    pub non_finite_count: usize,
    /// The first `MAX_NON_FINITE_LISTED` of them.
    pub non_finite: Vec<NonFinite>,
}

impl Verdict {
    /// Passes when sqrt(B) is within `threshold_sqrt_b` (normally `SQRT_B_THRESHOLD`), no
    /// tile fails and every value is finite.
    pub fn passes(&self, threshold_sqrt_b: f64) -> bool {
        self.non_finite_count == 0 && self.sqrt_b <= threshold_sqrt_b && self.tiles.failed() == 0
    }
}

impl fmt::Display for Verdict {
    /// One line, judged at `SQRT_B_THRESHOLD`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let outcome = if self.passes(SQRT_B_THRESHOLD) {
            "PASS"
        } else {
            "FAIL"
        };
        write!(
            f,
            "{outcome}: sqrt(B) {:.5} (limit {SQRT_B_THRESHOLD}), sqrt(V) {:.5}, tiles failed {}/{}, non-finite {}",
            self.sqrt_b,
            self.sqrt_v,
            self.tiles.failed(),
            self.tiles.tested,
            self.non_finite_count
        )?;
        if let Some(first) = self.non_finite.first() {
            write!(
                f,
                " (first: {} at ({}, {}) channel {})",
                first.image, first.x, first.y, first.channel
            )?;
        }
        if let Some(worst) = self
            .tiles
            .failures
            .iter()
            .max_by(|a, b| (a.d.abs() - a.threshold).total_cmp(&(b.d.abs() - b.threshold)))
        {
            write!(
                f,
                " (worst tile at pixel ({}, {}) channel {}: d {:+.5} > {:.5})",
                worst.x, worst.y, worst.channel, worst.d, worst.threshold
            )?;
        }
        write!(
            f,
            " [K={}, {}x{}]",
            self.replicates, self.width, self.height
        )
    }
}

/// Computes every statistic and the verdict's inputs at once.
pub fn evaluate(
    replicates: &[Image],
    reference: &Image,
    half_reference: &Image,
) -> Result<Verdict, StudyError> {
    check_inputs(replicates, reference, half_reference)?;
    let bias = bias_estimate(replicates, reference, half_reference)?;
    let noise = noise_variance(replicates)?;
    let tiles = tile_test(replicates, reference, half_reference)?;

    let mut non_finite = Vec::new();
    let mut non_finite_count = 0;
    let roles = replicates
        .iter()
        .enumerate()
        .map(|(k, image)| (ImageRole::Replicate(k), image))
        .chain([
            (ImageRole::Reference, reference),
            (ImageRole::HalfReference, half_reference),
        ]);
    for (role, image) in roles {
        for (x, y, channel) in image.non_finite() {
            non_finite_count += 1;
            if non_finite.len() < MAX_NON_FINITE_LISTED {
                non_finite.push(NonFinite {
                    image: role,
                    x,
                    y,
                    channel,
                });
            }
        }
    }

    Ok(Verdict {
        replicates: replicates.len(),
        width: reference.width,
        height: reference.height,
        bias,
        sqrt_b: bias.sqrt_b(),
        sqrt_v: noise.max(0.0).sqrt(),
        tiles,
        non_finite_count,
        non_finite,
    })
}

/// V: mean over pixels, channels and pairs a < b of (x_a - x_b)^2 / 2, which equals the
/// mean of the per-value unbiased sample variance (computed that way, in two passes, to
/// avoid cancellation).
pub fn noise_variance(replicates: &[Image]) -> Result<f64, StudyError> {
    check_replicates(replicates)?;
    let variance = per_value_variance(replicates);
    Ok(variance.iter().flatten().sum::<f64>() / (variance.len() * 3) as f64)
}

/// B on 4x4 block means; see `Bias`.
pub fn bias_estimate(
    replicates: &[Image],
    reference: &Image,
    half_reference: &Image,
) -> Result<Bias, StudyError> {
    check_inputs(replicates, reference, half_reference)?;
    let k = replicates.len() as f64;
    let r = block_means(
        &to_f64(reference),
        reference.width,
        reference.height,
        BIAS_BLOCK,
    );
    let r2 = block_means(
        &to_f64(half_reference),
        reference.width,
        reference.height,
        BIAS_BLOCK,
    );
    // For each block and channel: sum_k e_k and sum_k e_k^2, so that the mean over pairs of
    // e_a e_b is ((sum e)^2 - sum e^2) / (K (K - 1)).
    let mut sum = vec![[0.0f64; 3]; r.len()];
    let mut sum_sq = vec![[0.0f64; 3]; r.len()];
    for replicate in replicates {
        let x = block_means(
            &to_f64(replicate),
            reference.width,
            reference.height,
            BIAS_BLOCK,
        );
        for i in 0..r.len() {
            for c in 0..3 {
                let e = x[i][c] - r[i][c];
                sum[i][c] += e;
                sum_sq[i][c] += e * e;
            }
        }
    }
    let values = (r.len() * 3) as f64;
    let mut cross = 0.0;
    let mut reference_term = 0.0;
    for i in 0..r.len() {
        for c in 0..3 {
            cross += (sum[i][c] * sum[i][c] - sum_sq[i][c]) / (k * (k - 1.0));
            let dr = r[i][c] - r2[i][c];
            reference_term += dr * dr;
        }
    }
    let cross = cross / values;
    let reference_term = reference_term / values;
    Ok(Bias {
        b: cross - reference_term,
        cross,
        reference_term,
    })
}

/// Tests every 8x8 tile and channel: fail when |d_T| > delta_T + z* SE_T with
/// SE_T^2 = mean_T(s_i^2) / (K |T|) + tau_T^2; see the constants for delta_T and z*.
pub fn tile_test(
    replicates: &[Image],
    reference: &Image,
    half_reference: &Image,
) -> Result<TileReport, StudyError> {
    check_inputs(replicates, reference, half_reference)?;
    let (w, h) = (reference.width, reference.height);
    let k = replicates.len() as f64;
    let r = to_f64(reference);
    let mut mean = vec![[0.0f64; 3]; r.len()];
    for replicate in replicates {
        for (m, p) in mean.iter_mut().zip(&replicate.pixels) {
            for c in 0..3 {
                m[c] += f64::from(p[c]) / k;
            }
        }
    }
    let mean_minus_r: Vec<[f64; 3]> = mean
        .iter()
        .zip(&r)
        .map(|(m, r)| [m[0] - r[0], m[1] - r[1], m[2] - r[2]])
        .collect();
    let r_minus_r2: Vec<[f64; 3]> = r
        .iter()
        .zip(&half_reference.pixels)
        .map(|(r, r2)| {
            [
                r[0] - f64::from(r2[0]),
                r[1] - f64::from(r2[1]),
                r[2] - f64::from(r2[2]),
            ]
        })
        .collect();
    let variance = per_value_variance(replicates);

    let d = block_means(&mean_minus_r, w, h, TILE);
    let tau = block_means(&r_minus_r2, w, h, TILE);
    let s2 = block_means(&variance, w, h, TILE);
    let r_t = block_means(&r, w, h, TILE);
    let tiles_x = w.div_ceil(TILE);

    let mut report = TileReport::default();
    for i in 0..d.len() {
        let (tile_x, tile_y) = (i % tiles_x, i / tiles_x);
        let (x, y) = (tile_x * TILE, tile_y * TILE);
        let pixels = ((w - x).min(TILE) * (h - y).min(TILE)) as f64;
        for c in 0..3 {
            report.tested += 1;
            let standard_error = (s2[i][c] / (k * pixels) + tau[i][c] * tau[i][c]).sqrt();
            let threshold =
                TILE_ABS_TOLERANCE + TILE_REL_TOLERANCE * r_t[i][c].abs() + Z_STAR * standard_error;
            let within = d[i][c].abs() <= threshold;
            // A NaN d compares false, so it fails the tile rather than hiding.
            if !within {
                report.failures.push(TileFailure {
                    tile_x,
                    tile_y,
                    x,
                    y,
                    channel: c,
                    d: d[i][c],
                    threshold,
                    standard_error,
                    reference_mean: r_t[i][c],
                });
            }
        }
    }
    Ok(report)
}

/// RMSE, mean absolute and maximum absolute difference over all pixels and channels.
pub fn compare(a: &Image, b: &Image) -> Result<ImageDifference, StudyError> {
    check_image(a, "first image")?;
    check_same_size(a, b, "second image")?;
    let mut sum_sq = 0.0;
    let mut sum_abs = 0.0;
    let mut max_abs = 0.0;
    let mut max_at = (0, 0, 0);
    for (i, (p, q)) in a.pixels.iter().zip(&b.pixels).enumerate() {
        for c in 0..3 {
            let diff = f64::from(p[c]) - f64::from(q[c]);
            sum_sq += diff * diff;
            sum_abs += diff.abs();
            // NaN differences take the maximum so they cannot hide.
            if diff.abs() > max_abs || (diff.is_nan() && !f64::is_nan(max_abs)) {
                max_abs = diff.abs();
                max_at = (i % a.width, i / a.width, c);
            }
        }
    }
    let n = (a.pixels.len() * 3) as f64;
    Ok(ImageDifference {
        rmse: (sum_sq / n).sqrt(),
        mean_abs: sum_abs / n,
        max_abs,
        max_at,
    })
}

pub fn rmse(a: &Image, b: &Image) -> Result<f64, StudyError> {
    compare(a, b).map(|d| d.rmse)
}

pub fn mean_abs_error(a: &Image, b: &Image) -> Result<f64, StudyError> {
    compare(a, b).map(|d| d.mean_abs)
}

pub fn max_abs_error(a: &Image, b: &Image) -> Result<f64, StudyError> {
    compare(a, b).map(|d| d.max_abs)
}

fn to_f64(image: &Image) -> Vec<[f64; 3]> {
    image.pixels.iter().map(|p| p.map(f64::from)).collect()
}

/// Unbiased (K - 1) sample variance across replicates, per pixel and channel.
fn per_value_variance(replicates: &[Image]) -> Vec<[f64; 3]> {
    let k = replicates.len() as f64;
    let n = replicates[0].pixels.len();
    let mut mean = vec![[0.0f64; 3]; n];
    for replicate in replicates {
        for (m, p) in mean.iter_mut().zip(&replicate.pixels) {
            for c in 0..3 {
                m[c] += f64::from(p[c]);
            }
        }
    }
    for m in &mut mean {
        for v in m.iter_mut() {
            *v /= k;
        }
    }
    let mut variance = vec![[0.0f64; 3]; n];
    for replicate in replicates {
        for ((v, m), p) in variance.iter_mut().zip(&mean).zip(&replicate.pixels) {
            for c in 0..3 {
                let d = f64::from(p[c]) - m[c];
                v[c] += d * d;
            }
        }
    }
    for v in &mut variance {
        for x in v.iter_mut() {
            *x /= k - 1.0;
        }
    }
    variance
}

/// Means of `size` x `size` blocks, row-major; edge blocks average the pixels they hold.
fn block_means(values: &[[f64; 3]], width: usize, height: usize, size: usize) -> Vec<[f64; 3]> {
    let (bw, bh) = (width.div_ceil(size), height.div_ceil(size));
    let mut sums = vec![[0.0f64; 3]; bw * bh];
    let mut counts = vec![0usize; bw * bh];
    for y in 0..height {
        for x in 0..width {
            let b = (y / size) * bw + x / size;
            counts[b] += 1;
            for c in 0..3 {
                sums[b][c] += values[y * width + x][c];
            }
        }
    }
    for (s, &n) in sums.iter_mut().zip(&counts) {
        for v in s.iter_mut() {
            *v /= n as f64;
        }
    }
    sums
}

fn check_image(image: &Image, what: &str) -> Result<(), StudyError> {
    if image.width == 0 || image.height == 0 || image.pixels.len() != image.width * image.height {
        return Err(StudyError::InvalidImage {
            what: what.to_string(),
        });
    }
    Ok(())
}

fn check_same_size(expected: &Image, image: &Image, what: &str) -> Result<(), StudyError> {
    check_image(image, what)?;
    if !image.same_size(expected) {
        return Err(StudyError::SizeMismatch {
            what: what.to_string(),
            expected: (expected.width, expected.height),
            found: (image.width, image.height),
        });
    }
    Ok(())
}

fn check_replicates(replicates: &[Image]) -> Result<(), StudyError> {
    if replicates.len() < 2 {
        return Err(StudyError::TooFewReplicates {
            found: replicates.len(),
        });
    }
    check_image(&replicates[0], "replicate 0")?;
    for (k, replicate) in replicates.iter().enumerate().skip(1) {
        check_same_size(&replicates[0], replicate, &format!("replicate {k}"))?;
    }
    Ok(())
}

pub(crate) fn check_inputs(
    replicates: &[Image],
    reference: &Image,
    half_reference: &Image,
) -> Result<(), StudyError> {
    check_replicates(replicates)?;
    check_same_size(&replicates[0], reference, "reference")?;
    check_same_size(&replicates[0], half_reference, "half reference")
}

#[cfg(test)]
#[path = "metrics_tests.rs"]
mod tests;
