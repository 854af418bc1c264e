//! The phase-ensemble test, for scenes whose noise texture is larger than the distribution
//! test's blocks (a cloud sky that spans the image, a cloud plane whose one cell shadows all
//! the ground in view). There one phase of the noise decides every block, so POV-Ray's own
//! image moves by more than the distribution test allows when the texture is shifted, and
//! comparing one phase with another says nothing. Such scenes are listed with an anchor in
//! tests/corpus/phase-ensemble.txt: the text after which `translate <7k, 3k, 5k>` shifts
//! the noise (`shifted`).
//!
//! Both renderers render the same N shifted copies (penumbra one seed each, POV-Ray a
//! k-supersampled reference each). Per channel and 40x40 block, and pooled over all blocks,
//! the block mean averaged over the phases is compared: d = mean_k m(x_k) - mean_k m(r_k),
//! SE^2 = Var_k m(x_k) / N + Var_k m(r_k) / N (each phase is an independent draw of noise
//! phase and, for penumbra, of sampling), plus the references' own error (the mean over phases
//! of (m(r_k) - m(r_k/2))^2). A test fails when |d| > delta + t SE, delta as in the
//! distribution test, t the Student quantile at Welch's degrees of freedom for the Sidak
//! level of alpha = 1e-3 over all the tests. The pooled image's spread over the phases is
//! compared too (`record_spread`): a noise whose large scales vary more or less than
//! POV-Ray's fails there even when its mean agrees. Blocks the noise does not reach have no phase
//! spread, so a wrong colour, brightness, object or camera there fails as in the pixel test;
//! in the sky the test is as sharp as the phases' spread over sqrt(N) allows.

use super::judge::{DIST_ABS_TOLERANCE, DIST_BLOCK, DIST_REL_TOLERANCE, DistributionVerdict};
use super::judge::{DistributionFailure, sample_variance};
use crate::output::Image;
use crate::study::distribution::student_critical;
use crate::study::{Reference, StudyError};

/// Noise phases per scene.
pub const PHASES: usize = 16;
/// Supersampling of each phase's POV-Ray reference (the phases' spread dwarfs its error).
pub const PHASE_SUPERSAMPLE: u32 = 4;
/// Family-wise false-failure rate of one scene's tests.
const ALPHA: f64 = 1e-3;

/// Separates the anchors of one scene (a scene may have several noises whose features are
/// larger than the blocks: a cloud plane and a turbulent fog).
pub const ANCHOR_SEPARATOR: &str = ";;";

/// The scene text with `translate <7k, 3k, 5k>` after the first occurrence of each anchor,
/// or `None` when one is not in it. Phase 0 is the scene as written.
pub fn shifted(text: &[u8], anchors: &str, k: usize) -> Option<Vec<u8>> {
    let mut ends = Vec::new();
    for anchor in anchors.split(ANCHOR_SEPARATOR).map(str::trim) {
        let at = text
            .windows(anchor.len().max(1))
            .position(|w| w == anchor.as_bytes())?;
        ends.push(at + anchor.len());
    }
    ends.sort_unstable();
    let shift = format!(" translate <{}, {}, {}>", 7 * k, 3 * k, 5 * k);
    let mut out = Vec::with_capacity(text.len() + ends.len() * shift.len());
    let mut last = 0;
    for end in ends {
        out.extend_from_slice(&text[last..end]);
        if k > 0 {
            out.extend_from_slice(shift.as_bytes());
        }
        last = end;
    }
    out.extend_from_slice(&text[last..]);
    Some(out)
}

/// The test described in the module documentation: `penumbra[k]` and `povray[k]` render
/// phase k.
pub fn ensemble_test(
    penumbra: &[Image],
    povray: &[Reference],
) -> Result<DistributionVerdict, StudyError> {
    if penumbra.len() != povray.len() || penumbra.len() < 2 {
        return Err(StudyError::TooFewReplicates {
            found: penumbra.len().min(povray.len()),
        });
    }
    let (w, h) = (povray[0].full.width, povray[0].full.height);
    for image in penumbra
        .iter()
        .chain(povray.iter().flat_map(|r| [&r.full, &r.half]))
    {
        if (image.width, image.height) != (w, h) {
            return Err(StudyError::SizeMismatch {
                what: "a phase's image".into(),
                expected: (w, h),
                found: (image.width, image.height),
            });
        }
    }
    let blocks = blocks(w, h);
    // Means per block and pooled, and the pooled spread, per channel.
    let tests = (blocks.len() + 2) * 3;
    let mut verdict = DistributionVerdict::default();
    for channel in 0..3 {
        let mut pooled = Samples::zero(penumbra.len());
        for &block in &blocks {
            let s = Samples::of(penumbra, povray, block, channel);
            pooled.add(&s);
            record(&mut verdict, Some(block.origin), channel, &s, (1.0, tests));
        }
        let units = (blocks.len() as f64, tests);
        record(&mut verdict, None, channel, &pooled, units);
        record_spread(&mut verdict, channel, &pooled, units);
    }
    Ok(verdict)
}

/// Tests the pooled image's spread over the phases: the noise's large scales must vary as
/// much from phase to phase in penumbra as in POV-Ray. ln(s_x^2 / s_r^2) is about normal with
/// variance 2 / (N - 1) for each of the two (Bartlett); each variance gets the mean test's
/// squared tolerance added, so that spreads smaller than what the mean test allows (and
/// penumbra's own sampling noise, which POV-Ray's references lack) do not count.
fn record_spread(
    verdict: &mut DistributionVerdict,
    channel: usize,
    s: &Samples,
    (blocks, tests): (f64, usize),
) {
    let n = s.x.len() as f64;
    let floor = (DIST_ABS_TOLERANCE * blocks).powi(2);
    let (vx, vr) = (sample_variance(&s.x) + floor, sample_variance(&s.r) + floor);
    verdict.check(DistributionFailure {
        block: None,
        channel,
        statistic: "phase spread (ln variance ratio)",
        d: (vx / vr).ln(),
        threshold: student_critical(ALPHA, tests, f64::INFINITY) * (4.0 / (n - 1.0)).sqrt(),
        reference: vr.sqrt(),
    });
}

#[derive(Debug, Clone, Copy)]
struct Block {
    origin: (usize, usize),
    x0: usize,
    y0: usize,
    x1: usize,
    y1: usize,
}

fn blocks(w: usize, h: usize) -> Vec<Block> {
    let mut out = Vec::new();
    for by in 0..h.div_ceil(DIST_BLOCK) {
        for bx in 0..w.div_ceil(DIST_BLOCK) {
            out.push(Block {
                origin: (bx, by),
                x0: bx * DIST_BLOCK,
                y0: by * DIST_BLOCK,
                x1: ((bx + 1) * DIST_BLOCK).min(w),
                y1: ((by + 1) * DIST_BLOCK).min(h),
            });
        }
    }
    out
}

fn block_mean(image: &Image, b: Block, channel: usize) -> f64 {
    let mut sum = 0.0;
    for y in b.y0..b.y1 {
        for x in b.x0..b.x1 {
            sum += f64::from(image.get(x, y)[channel]);
        }
    }
    sum / ((b.x1 - b.x0) * (b.y1 - b.y0)) as f64
}

/// Per phase: penumbra's block mean, POV-Ray's, and POV-Ray's at k/2. Summed over blocks for
/// the pooled test.
#[derive(Debug, Clone, Default)]
struct Samples {
    x: Vec<f64>,
    r: Vec<f64>,
    half: Vec<f64>,
}

impl Samples {
    fn of(penumbra: &[Image], povray: &[Reference], b: Block, channel: usize) -> Samples {
        Samples {
            x: penumbra.iter().map(|i| block_mean(i, b, channel)).collect(),
            r: povray
                .iter()
                .map(|p| block_mean(&p.full, b, channel))
                .collect(),
            half: povray
                .iter()
                .map(|p| block_mean(&p.half, b, channel))
                .collect(),
        }
    }

    fn zero(n: usize) -> Samples {
        Samples {
            x: vec![0.0; n],
            r: vec![0.0; n],
            half: vec![0.0; n],
        }
    }

    fn add(&mut self, other: &Samples) {
        for (mine, theirs) in [
            (&mut self.x, &other.x),
            (&mut self.r, &other.r),
            (&mut self.half, &other.half),
        ] {
            mine.iter_mut().zip(theirs).for_each(|(m, t)| *m += t);
        }
    }
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// Tests one block (or the pooled sum of `blocks` blocks) and records a failure; `tests` is
/// the size of the family the level is shared by.
fn record(
    verdict: &mut DistributionVerdict,
    block: Option<(usize, usize)>,
    channel: usize,
    s: &Samples,
    (blocks, tests): (f64, usize),
) {
    let n = s.x.len() as f64;
    let (vx, vr) = (sample_variance(&s.x) / n, sample_variance(&s.r) / n);
    let reference_error =
        s.r.iter()
            .zip(&s.half)
            .map(|(r, h)| (r - h).powi(2))
            .sum::<f64>()
            / n;
    let reference = mean(&s.r);
    let d = mean(&s.x) - reference;
    let se = (vx + vr + reference_error).sqrt();
    let threshold = DIST_ABS_TOLERANCE * blocks
        + DIST_REL_TOLERANCE * reference.abs()
        + student_critical(ALPHA, tests, welch_df(vx, vr, n)) * se;
    verdict.check(DistributionFailure {
        block,
        channel,
        statistic: "phase mean",
        d,
        threshold,
        reference,
    });
}

/// Welch-Satterthwaite degrees of freedom of vx + vr (each a variance of a mean of n), at
/// least n - 1.
fn welch_df(vx: f64, vr: f64, n: f64) -> f64 {
    let df = (vx + vr).powi(2) / ((vx * vx + vr * vr) / (n - 1.0));
    if df.is_finite() {
        df.max(n - 1.0)
    } else {
        n - 1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A uniform value in [-0.5, 0.5) from a seed (SplitMix64).
    fn uniform(seed: u64) -> f64 {
        let mut z = seed.wrapping_add(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64 - 0.5
    }

    /// A phase of a scene: a sky (top half) whose brightness the phase moves by up to
    /// +-0.15, over a ground whose colour is fixed, plus per-pixel sampling noise.
    fn phase(seed: u64, sky_offset: f64, ground_gain: f32) -> Image {
        phase_spread(seed, sky_offset, ground_gain, 1.0)
    }

    fn phase_spread(seed: u64, sky_offset: f64, ground_gain: f32, spread: f64) -> Image {
        let sky = 0.5 + 0.3 * spread * uniform(seed);
        Image::from_fn(160, 120, |x, y| {
            let noise = 0.02 * uniform(seed * 100_003 + (y * 160 + x) as u64) as f32;
            if y < 60 {
                [(sky + sky_offset) as f32 + noise; 3]
            } else {
                [
                    0.3 * ground_gain + noise,
                    0.4 * ground_gain + noise,
                    0.2 + noise,
                ]
            }
        })
    }

    fn references(seed: u64) -> Vec<Reference> {
        (0..PHASES as u64)
            .map(|k| Reference {
                full: phase(seed + k, 0.0, 1.0),
                half: phase(seed + k, 0.0, 1.0),
                supersample: PHASE_SUPERSAMPLE,
                povray_seconds: 1.0,
            })
            .collect()
    }

    fn penumbra(seed: u64, sky_offset: f64, ground_gain: f32) -> Vec<Image> {
        (0..PHASES as u64)
            .map(|k| phase(seed + k, sky_offset, ground_gain))
            .collect()
    }

    #[test]
    fn the_same_scene_passes_at_other_phases_and_a_wrong_one_fails() {
        let povray = references(1000);
        // Other phases than POV-Ray's: the sky's spread is large, its mean the same.
        let same = ensemble_test(&penumbra(5000, 0.0, 1.0), &povray).expect("test");
        assert!(same.passes(), "{same}");
        // A 10% darker ground: no phase spread there, so it fails block by block.
        let dark = ensemble_test(&penumbra(5000, 0.0, 0.9), &povray).expect("test");
        assert!(
            !dark.passes() && dark.failures.iter().any(|f| f.block.is_some()),
            "{dark}"
        );
        // A sky 0.3 too bright (3.5 times the phases' SD of 0.087): beyond what 16 phases
        // allow (the threshold is about 5.5 SE, SE = 0.087 sqrt(2 / 16) = 0.031).
        let bright = ensemble_test(&penumbra(5000, 0.3, 1.0), &povray).expect("test");
        assert!(!bright.passes(), "{bright}");
        // The same mean, but a sky that varies 4 times as much from phase to phase: the
        // means pass, the spread fails (ln 16 = 2.8 against a threshold near 2.2).
        let wild: Vec<Image> = (0..PHASES as u64)
            .map(|k| phase_spread(5000 + k, 0.0, 1.0, 4.0))
            .collect();
        let wild = ensemble_test(&wild, &povray).expect("test");
        assert!(
            !wild.passes()
                && wild
                    .failures
                    .iter()
                    .all(|f| f.statistic.starts_with("phase spread")),
            "{wild}"
        );
    }

    #[test]
    fn mismatched_inputs_are_errors() {
        let povray = references(1);
        assert!(ensemble_test(&penumbra(2, 0.0, 1.0)[..3], &povray).is_err());
        let small = vec![Image::from_fn(80, 60, |_, _| [0.0; 3]); PHASES];
        assert!(ensemble_test(&small, &povray).is_err());
    }

    #[test]
    fn the_shift_goes_after_the_anchor() {
        let text = b"sky_sphere { S_Cloud5 } plane { y, 0 pigment { S_Cloud5 } }";
        let out = shifted(text, "sky_sphere { S_Cloud5", 2).expect("anchor");
        assert_eq!(
            out,
            b"sky_sphere { S_Cloud5 translate <14, 6, 10> } plane { y, 0 pigment { S_Cloud5 } }"
        );
        assert_eq!(shifted(text, "S_Cloud5", 0).expect("anchor"), text);
        assert!(shifted(text, "bozo", 1).is_none());
        assert!(shifted(text, "S_Cloud5 ;; bozo", 1).is_none());
        // Several anchors, in any order: each first occurrence is shifted.
        let both = shifted(text, "y, 0 ;; sky_sphere {", 1).expect("anchors");
        assert_eq!(
            both,
            b"sky_sphere { translate <7, 3, 5> S_Cloud5 } plane { y, 0 translate <7, 3, 5> pigment { S_Cloud5 } }"
        );
    }
}
