//! The verdicts: the pixel test of testing-statistics.md (sqrt(B) on 4x4 block means and
//! the 8x8 tile test), and, for scenes whose textures use POV-Ray's noise, a distribution
//! test blind to the noise's phase.
//!
//! The distribution test compares, per channel and per 40x40 block (4 x 3 blocks at
//! 160x120), four statistics of the pixel values: the mean and the 10%, 50% and 90%
//! quantiles. For each, d = S(xbar) - S(r) with xbar the per-pixel mean of the K replicates
//! and r the k reference. A block fails when |d| > delta + z SE, where
//! - delta = 0.005 + 0.02 |S(r)| (as the tile test: half-float reference, shading round-off;
//!   penumbra's noise has POV-Ray's value distribution, tests/appearance_noise.rs);
//!   for the quantiles plus 1.28 s, s the RMS per-pixel SD of xbar: noise widens xbar's
//!   value distribution, which biases its 10% and 90% quantiles outward by up to 1.28 s
//!   (the 90% quantile of N(0, s^2)), an effect the replicates' variance does not cover;
//! - SE^2 = sigma_sampling^2 + sigma_texture^2 + (S(r_k) - S(r_k/2))^2;
//! - sigma_sampling^2 = Var_k S(x_k) / K, the replicates' own spread of the statistic;
//! - sigma_texture^2 = Var(d over the block's 16 10x10 sub-blocks) / 4. The scene's layout is
//!   the same in penumbra's image and POV-Ray's, so it cancels in a sub-block's d; what is
//!   left is the noise's phase (and sampling). If the 16 sub-block differences were
//!   independent, the block's d (their mean, for the mean statistic; about so for quantiles)
//!   would have their variance / 16; noise correlated over neighbouring sub-blocks makes them
//!   alike, so they are counted as 4 independent ones (twice the independent SE). A block's
//!   quantile may be set by the pixels of a few sub-blocks (where a block is part sky, part
//!   texture), so for quantiles the divisor is 1 (a sub-block's own variance). A constant
//!   offset does not widen it (it moves every sub-block alike), a gain only by the gain
//!   times the layout's spread;
//! - z = 4 (Sidak: alpha = 1e-3 over 12 blocks x 3 channels x 4 statistics = 144 tests
//!   gives 3.97).
//!
//! The same terms summed over all blocks make a second, pooled test per channel and
//! statistic (sum d against sum delta + z sqrt(sum SE^2)): a change of the whole image adds
//! up over the blocks while independent texture and sampling noise add up as a square root,
//! so it sees a gain or offset about sqrt(12) times smaller than one block does.
//!
//! It catches what moves a block's distribution by more than its own internal spread: a
//! wrong colour or brightness (a 10% gain, an offset of 0.03), a missing or moved object, a
//! wrong camera; not a sub-block shift of detail inside a busy block.

use super::super::{SQRT_B_THRESHOLD, StudyError, Verdict, evaluate};
use crate::output::Image;
use crate::study::Reference;
use std::fmt;

/// Side of the distribution test's blocks, in pixels.
pub const DIST_BLOCK: usize = 40;
pub const DIST_Z: f64 = 4.0;
/// A quantile of xbar may sit this many times xbar's noise (RMS per-pixel SD) outside the
/// reference's: the 90% quantile of N(0, s^2) is 1.28 s.
pub const DIST_QUANTILE_NOISE: f64 = 1.28;
/// Each block is split into this many sub-blocks per side for the texture variance.
pub const DIST_SPLIT: usize = 4;
/// For the mean, the 16 sub-blocks' differences count as this many independent ones (noise
/// correlated over neighbouring sub-blocks): Var(block d) = Var(sub-block d) / 4, not / 16.
/// For the quantiles, as one: a block's quantile may be set by the pixels of a few
/// sub-blocks (the textured part of a block), so it varies up to as much as one does.
pub const DIST_EFFECTIVE_UNITS: [f64; 4] = [4.0, 1.0, 1.0, 1.0];
pub const DIST_ABS_TOLERANCE: f64 = 0.005;
pub const DIST_REL_TOLERANCE: f64 = 0.02;
/// The statistics, by name: the mean, then quantiles.
pub const DIST_STATISTICS: [&str; 4] = ["mean", "q10", "q50", "q90"];
const QUANTILES: [f64; 3] = [0.1, 0.5, 0.9];

/// Which test decides a scene.
#[derive(Debug, Clone, PartialEq)]
pub enum TestKind {
    /// Pixel by pixel: sqrt(B) and the tile test.
    Pixel,
    /// Blind to the noise's phase; the noise words found in the scene.
    Distribution(Vec<String>),
}

/// One block, channel and statistic outside its tolerance.
#[derive(Debug, Clone, PartialEq)]
pub struct DistributionFailure {
    /// Block column and row; `None` for the sum over all blocks.
    pub block: Option<(usize, usize)>,
    pub channel: usize,
    pub statistic: &'static str,
    pub d: f64,
    pub threshold: f64,
    pub reference: f64,
}

#[derive(Debug, Clone, PartialEq, Default)]
pub struct DistributionVerdict {
    /// (block, channel, statistic) triples tested, and the 12 pooled (channel, statistic) pairs.
    pub tested: usize,
    pub failures: Vec<DistributionFailure>,
    /// Largest |d| / threshold over all tests (< 1 passes).
    pub worst_ratio: f64,
}

impl DistributionVerdict {
    pub fn passes(&self) -> bool {
        self.tested > 0 && self.failures.is_empty() && self.worst_ratio.is_finite()
    }

    /// Counts one test, |d| against its threshold, and keeps it when it fails (or when
    /// either is not a number).
    pub fn check(&mut self, test: DistributionFailure) {
        let ratio = test.d.abs() / test.threshold;
        self.tested += 1;
        self.worst_ratio = if ratio.is_finite() {
            self.worst_ratio.max(ratio)
        } else {
            f64::INFINITY
        };
        if test.d.is_nan() || test.threshold.is_nan() || test.d.abs() > test.threshold {
            self.failures.push(test);
        }
    }
}

impl fmt::Display for DistributionVerdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let outcome = if self.passes() { "PASS" } else { "FAIL" };
        write!(
            f,
            "{outcome}: blocks failed {}/{}, worst |d|/threshold {:.2}",
            self.failures.len(),
            self.tested,
            self.worst_ratio
        )?;
        if let Some(w) = self
            .failures
            .iter()
            .max_by(|a, b| (a.d.abs() / a.threshold).total_cmp(&(b.d.abs() / b.threshold)))
        {
            let place = w.block.map_or_else(
                || "all blocks summed".to_string(),
                |(x, y)| format!("block ({x}, {y})"),
            );
            write!(
                f,
                " (worst: {place} channel {} {}: d {:+.4} > {:.4}, reference {:.4})",
                w.channel, w.statistic, w.d, w.threshold, w.reference
            )?;
        }
        Ok(())
    }
}

/// Both verdicts; `kind` says which decides.
#[derive(Debug, Clone, PartialEq)]
pub struct Judgement {
    pub kind: TestKind,
    pub pixel: Verdict,
    /// Computed for every scene (it is cheap), decisive for `TestKind::Distribution`.
    pub distribution: DistributionVerdict,
    /// For scenes listed in tests/corpus/phase-ensemble.txt, the phase-ensemble test
    /// (`ensemble`), which decides instead of the distribution test.
    pub ensemble: Option<DistributionVerdict>,
}

impl Judgement {
    pub fn passes(&self) -> bool {
        match self.kind {
            TestKind::Pixel => self.pixel.passes(SQRT_B_THRESHOLD),
            TestKind::Distribution(_) => match &self.ensemble {
                Some(ensemble) => ensemble.passes() && self.pixel.non_finite_count == 0,
                None => self.distribution.passes(),
            },
        }
    }

    /// The decisive verdict in one line, the other after it.
    pub fn summary(&self) -> String {
        match self.kind {
            TestKind::Pixel => format!("{}; distribution {}", self.pixel, self.distribution),
            TestKind::Distribution(_) => match &self.ensemble {
                Some(ensemble) => format!(
                    "phase ensemble {ensemble}; distribution {}; pixel {}",
                    self.distribution, self.pixel
                ),
                None => format!("{}; pixel {}", self.distribution, self.pixel),
            },
        }
    }
}

/// Judges K replicates against a reference with the test `kind` names.
pub fn judge(
    kind: &TestKind,
    replicates: &[Image],
    reference: &Reference,
) -> Result<Judgement, StudyError> {
    let pixel = evaluate(replicates, &reference.full, &reference.half)?;
    let distribution = distribution_test(replicates, &reference.full, &reference.half)?;
    Ok(Judgement {
        kind: kind.clone(),
        pixel,
        distribution,
        ensemble: None,
    })
}

/// The per-pixel mean of the replicates.
pub fn mean_image(replicates: &[Image]) -> Image {
    let first = &replicates[0];
    let k = replicates.len() as f64;
    Image::from_fn(first.width, first.height, |x, y| {
        let mut sum = [0.0f64; 3];
        for r in replicates {
            let p = r.get(x, y);
            for c in 0..3 {
                sum[c] += f64::from(p[c]);
            }
        }
        sum.map(|s| (s / k) as f32)
    })
}

/// A rectangle of pixels, `x0..x1` by `y0..y1`.
#[derive(Debug, Clone, Copy)]
struct Rect {
    x0: usize,
    y0: usize,
    x1: usize,
    y1: usize,
}

impl Rect {
    /// `n` x `n` parts (empty ones left out).
    fn split(&self, n: usize) -> Vec<Rect> {
        let xs = |i: usize| self.x0 + (self.x1 - self.x0) * i / n;
        let ys = |j: usize| self.y0 + (self.y1 - self.y0) * j / n;
        let mut parts = Vec::with_capacity(n * n);
        for j in 0..n {
            for i in 0..n {
                let r = Rect {
                    x0: xs(i),
                    y0: ys(j),
                    x1: xs(i + 1),
                    y1: ys(j + 1),
                };
                if r.x1 > r.x0 && r.y1 > r.y0 {
                    parts.push(r);
                }
            }
        }
        parts
    }
}

/// Mean, then `QUANTILES`, of one channel over a rectangle.
fn statistics(image: &Image, rect: Rect, channel: usize) -> [f64; 4] {
    let mut values = Vec::with_capacity((rect.x1 - rect.x0) * (rect.y1 - rect.y0));
    for y in rect.y0..rect.y1 {
        for x in rect.x0..rect.x1 {
            values.push(f64::from(image.get(x, y)[channel]));
        }
    }
    if values.is_empty() {
        return [f64::NAN; 4];
    }
    let mean = values.iter().sum::<f64>() / values.len() as f64;
    values.sort_by(f64::total_cmp);
    let q = QUANTILES.map(|q| super::super::distribution::quantile(&values, q));
    [mean, q[0], q[1], q[2]]
}

pub(super) fn sample_variance(values: &[f64]) -> f64 {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0)
}

/// The distribution test described in the module documentation.
pub fn distribution_test(
    replicates: &[Image],
    reference: &Image,
    half_reference: &Image,
) -> Result<DistributionVerdict, StudyError> {
    super::super::metrics::check_inputs(replicates, reference, half_reference)?;
    let mean = mean_image(replicates);
    let mut verdict = DistributionVerdict::default();
    let (w, h) = (reference.width, reference.height);
    // Summed over all blocks, per channel and statistic: a change of the whole image (a
    // gain, an offset) adds up over blocks while the noise adds up as a square root.
    let mut sums = [[Term::default(); 4]; 3];
    for by in 0..h.div_ceil(DIST_BLOCK) {
        for bx in 0..w.div_ceil(DIST_BLOCK) {
            let rect = Rect {
                x0: bx * DIST_BLOCK,
                y0: by * DIST_BLOCK,
                x1: ((bx + 1) * DIST_BLOCK).min(w),
                y1: ((by + 1) * DIST_BLOCK).min(h),
            };
            for (channel, sum) in sums.iter_mut().enumerate() {
                let block = BlockInputs {
                    replicates,
                    mean: &mean,
                    reference,
                    half_reference,
                    rect,
                    channel,
                };
                for (i, term) in block_terms(&block).iter().enumerate() {
                    record(
                        &mut verdict,
                        Some((bx, by)),
                        channel,
                        DIST_STATISTICS[i],
                        term,
                    );
                    sum[i].add(term);
                }
            }
        }
    }
    for (channel, sum) in sums.iter().enumerate() {
        for (i, term) in sum.iter().enumerate() {
            record(&mut verdict, None, channel, DIST_STATISTICS[i], term);
        }
    }
    Ok(verdict)
}

struct BlockInputs<'a> {
    replicates: &'a [Image],
    mean: &'a Image,
    reference: &'a Image,
    half_reference: &'a Image,
    rect: Rect,
    channel: usize,
}

/// One statistic of one block (or, summed, of all blocks): the difference, the fixed
/// tolerance and the variance of the difference.
#[derive(Debug, Clone, Copy, Default)]
struct Term {
    d: f64,
    tolerance: f64,
    variance: f64,
    reference: f64,
}

impl Term {
    fn add(&mut self, other: &Term) {
        self.d += other.d;
        self.tolerance += other.tolerance;
        self.variance += other.variance;
        self.reference += other.reference;
    }
}

/// The RMS over the block of the per-pixel standard deviation of the replicates' mean: the
/// noise left in xbar, which widens its value distribution (a quantile of a noisy image is
/// biased outward; its mean is not).
fn mean_noise_sd(b: &BlockInputs) -> f64 {
    let k = b.replicates.len();
    let mut sum = 0.0;
    let mut count = 0usize;
    for y in b.rect.y0..b.rect.y1 {
        for x in b.rect.x0..b.rect.x1 {
            let values: Vec<f64> = b
                .replicates
                .iter()
                .map(|r| f64::from(r.get(x, y)[b.channel]))
                .collect();
            sum += sample_variance(&values) / k as f64;
            count += 1;
        }
    }
    (sum / count.max(1) as f64).sqrt()
}

fn block_terms(b: &BlockInputs) -> [Term; 4] {
    let s_x = statistics(b.mean, b.rect, b.channel);
    let s_r = statistics(b.reference, b.rect, b.channel);
    let s_r2 = statistics(b.half_reference, b.rect, b.channel);
    let per_replicate: Vec<[f64; 4]> = b
        .replicates
        .iter()
        .map(|x| statistics(x, b.rect, b.channel))
        .collect();
    // The differences of the statistics on the 4 x 4 sub-blocks: the scene's layout is the
    // same in both images and cancels; what remains is the noise's phase and sampling.
    let sub_d: Vec<[f64; 4]> = b
        .rect
        .split(DIST_SPLIT)
        .iter()
        .map(|&q| {
            let (x, r) = (
                statistics(b.mean, q, b.channel),
                statistics(b.reference, q, b.channel),
            );
            std::array::from_fn(|i| x[i] - r[i])
        })
        .collect();
    let k = b.replicates.len() as f64;
    let noise = mean_noise_sd(b);
    std::array::from_fn(|i| {
        let sampling = sample_variance(&per_replicate.iter().map(|s| s[i]).collect::<Vec<_>>()) / k;
        let texture = if sub_d.len() > 1 {
            sample_variance(&sub_d.iter().map(|s| s[i]).collect::<Vec<_>>())
                / DIST_EFFECTIVE_UNITS[i]
        } else {
            0.0
        };
        Term {
            d: s_x[i] - s_r[i],
            tolerance: DIST_ABS_TOLERANCE
                + DIST_REL_TOLERANCE * s_r[i].abs()
                + if i > 0 {
                    DIST_QUANTILE_NOISE * noise
                } else {
                    0.0
                },
            variance: sampling + texture + (s_r[i] - s_r2[i]).powi(2),
            reference: s_r[i],
        }
    })
}

/// Tests one term: fails when |d| > tolerance + z sqrt(variance).
fn record(
    verdict: &mut DistributionVerdict,
    block: Option<(usize, usize)>,
    channel: usize,
    statistic: &'static str,
    t: &Term,
) {
    verdict.check(DistributionFailure {
        block,
        channel,
        statistic,
        d: t.d,
        threshold: t.tolerance + DIST_Z * t.variance.sqrt(),
        reference: t.reference,
    });
}
