//! The noise fractals f_hetero_mf (29), f_ridge (58) and f_ridged_mf (59). Each algorithm
//! was recovered exactly from POV-Ray: its printed values equal these formulas applied to
//! the values POV-Ray prints for f_noise_generator at the scaled points (to 1e-11, over
//! random points and parameters, generators 2 and 3). penumbra's noise is its own
//! (src/appearance/noise.rs), so the results match POV-Ray's in distribution only.
//! Generator 1 differs slightly more: POV-Ray's fractals read its noise unclamped, while
//! penumbra's generator 1 is clamped to [0, 1] as f_noise_generator prints it.

use std::cell::RefCell;

use glam::DVec3;

use crate::appearance::noise::noise_with;

/// Octaves beyond this many are not computed: POV-Ray loops as long as asked, but by then
/// the frequency is lacunarity⁶⁴ and each octave costs a noise evaluation.
const MAX_OCTAVES: f64 = 64.0;

/// Coordinates are held within this: far beyond it floats are integers and penumbra's
/// lattice indices would overflow.
const FAR: f64 = 4.5e15;

/// The octaves' weights of the last (H, lacunarity) used on this thread
/// ([`octave_weight`]).
struct Weights {
    key: (u64, u64),
    len: usize,
    of: [f64; MAX_OCTAVES as usize + 1],
}

thread_local! {
    static WEIGHTS: RefCell<Weights> = const {
        RefCell::new(Weights {
            key: (u64::MAX, u64::MAX),
            len: 0,
            of: [0.0; MAX_OCTAVES as usize + 1],
        })
    };
}

/// `frequency.powf(-h)` for octave `k` (1, 2, ...), whose frequency is the lacunarity
/// multiplied in k times (as the loops compute it), so that the power is a function of
/// (h, lacunarity, k) and is kept per thread for the last pair: a function's parameters
/// are nearly always constants, and the powers were a ninth of advanced/benchmark's
/// instructions (f_ridged_mf of eight octaves, 4,800 instructions an evaluation).
fn octave_weight(h: f64, lacunarity: f64, k: usize, frequency: f64) -> f64 {
    WEIGHTS.with_borrow_mut(|w| {
        let key = (h.to_bits(), lacunarity.to_bits());
        if w.key != key {
            *w = Weights { key, len: 1, ..*w };
        }
        if let Some(&v) = w.of.get(k).filter(|_| k < w.len) {
            return v;
        }
        let v = frequency.powf(-h);
        if k == w.len && k < w.of.len() {
            w.of[k] = v;
            w.len += 1;
        }
        v
    })
}

/// Noise in [0, 1] under generator `g` (out-of-range values read as the default).
fn unit_noise(p: DVec3, g: f64) -> f64 {
    let g = if (1.0..=3.0).contains(&g) { g as u8 } else { 2 };
    noise_with(p.clamp(DVec3::splat(-FAR), DVec3::splat(FAR)), g)
}

fn octaves(n: f64) -> f64 {
    n.min(MAX_OCTAVES)
}

/// 59, 29, 58 under penumbra's noise with the generator P5.
pub fn ridged_mf(p: DVec3, a: &[f64]) -> f64 {
    ridged_mf_with(p, a, |q| unit_noise(q, a[5]))
}

pub fn hetero_mf(p: DVec3, a: &[f64]) -> f64 {
    hetero_mf_with(p, a, |q| unit_noise(q, a[5]))
}

pub fn ridge(p: DVec3, a: &[f64]) -> f64 {
    ridge_with(p, a, |q| unit_noise(q, a[5]))
}

/// 59: Musgrave's ridged multifractal over `noise` (in [0, 1]): P0 = H, P1 = lacunarity,
/// P2 = octaves (octave i is taken while i < P2, so 3.2 gives four), P3 = offset,
/// P4 = gain.
pub fn ridged_mf_with(p: DVec3, a: &[f64], noise: impl Fn(DVec3) -> f64) -> f64 {
    let (h, lacunarity, offset, gain) = (a[0], a[1], a[3], a[4]);
    let ridge = |q: DVec3| {
        let s = offset - (2.0 * noise(q) - 1.0).abs();
        s * s
    };
    let mut signal = ridge(p);
    let mut sum = signal;
    let (mut q, mut frequency, mut i, mut k) = (p, 1.0, 1.0, 1);
    while i < octaves(a[2]) {
        q *= lacunarity;
        frequency *= lacunarity;
        let weight = (signal * gain).clamp(0.0, 1.0);
        signal = ridge(q) * weight;
        sum += signal * octave_weight(h, lacunarity, k, frequency);
        i += 1.0;
        k += 1;
    }
    sum
}

/// 29: Musgrave's hetero terrain over `noise`, P0 = H, P1 = lacunarity, P2 = octaves,
/// P3 = offset. P4 ("T") is the power of the value that scales each octave, taken as
/// max(⌊P4⌋, 0) (measured: 0.3 and 0.5 act as 0, 1.5 as 1, 2.7 as 2, negatives as 0; 1
/// is Musgrave's). Octave i is taken while i < P2; a fractional part of P2 then adds that
/// fraction of one more octave, scaled by the value itself whatever P4 is.
pub fn hetero_mf_with(p: DVec3, a: &[f64], noise: impl Fn(DVec3) -> f64) -> f64 {
    let (h, lacunarity, offset) = (a[0], a[1], a[3]);
    let signed = |q: DVec3| 2.0 * noise(q) - 1.0;
    let power = a[4].floor().max(0.0).min(f64::from(i32::MAX)) as i32;
    let n = octaves(a[2]);
    let mut value = offset + signed(p);
    let (mut q, mut frequency, mut i, mut k) = (p, 1.0, 1.0, 0);
    let mut octave = || {
        q *= lacunarity;
        frequency *= lacunarity;
        k += 1;
        (signed(q) + offset) * octave_weight(h, lacunarity, k, frequency)
    };
    while i < n {
        value += octave() * value.powi(power);
        i += 1.0;
    }
    let rest = n - n.trunc();
    if rest > 0.0 {
        value += rest * octave() * value;
    }
    value
}

/// 58: a normalised sum of ridged octaves of `noise`, P0 = λ (frequency factor),
/// P1 = octaves, P2 = ω (amplitude factor), P3 = offset, P4 = ridge. Each octave is the
/// noise's distance from the ridge level, |N - ridge| / max(ridge, 1 - ridge), shifted and
/// scaled by the offset, (d - offset) / max(offset, 1 - offset); the sum is divided by
/// the sum of the amplitudes. At least one octave is taken; a fractional part of P1 adds
/// that fraction of the next octave to both sums.
pub fn ridge_with(p: DVec3, a: &[f64], noise: impl Fn(DVec3) -> f64) -> f64 {
    let (lambda, omega, offset, level) = (a[0], a[2], a[3], a[4]);
    let n = octaves(a[1]);
    let octave = |q: DVec3| {
        let d = (noise(q) - level).abs() / level.max(1.0 - level);
        (d - offset) / offset.max(1.0 - offset)
    };
    let whole = n.trunc().max(1.0);
    let (mut sum, mut weights) = (0.0, 0.0);
    let (mut q, mut amplitude, mut i) = (p, 1.0, 0.0);
    while i < whole {
        sum += amplitude * octave(q);
        weights += amplitude;
        q *= lambda;
        amplitude *= omega;
        i += 1.0;
    }
    let rest = n - n.trunc();
    if rest > 0.0 {
        sum += rest * amplitude * octave(q);
        weights += rest * amplitude;
    }
    sum / weights
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The kept weights are the powers themselves, bit for bit, whatever order the octaves
    /// and parameter pairs come in: pairs alternating (the memo replaced each time), octave
    /// counts growing and shrinking, an octave asked for before the ones below it, and
    /// more octaves than are kept.
    #[test]
    fn kept_octave_weights_are_the_powers() {
        let mut next = crate::geometry::uniform_stream(0x0c7a_7e5e_ed5a_1e01);
        // Two H and two lacunarities, each pair differing from another in one of them.
        let (h, l) = ([next() * 2.0 - 0.5, next()], [1.5 + next() * 3.0, 2.0]);
        let pairs = [(h[0], l[0]), (h[0], l[1]), (h[1], l[0]), (h[1], l[1])];
        for round in 0..400 {
            let (h, lacunarity) = pairs[(next() * 4.0) as usize % 4];
            let octaves = 1 + (next() * 70.0) as usize;
            let skip = round % 7 == 0;
            let mut frequency = 1.0;
            for k in 1..=octaves {
                frequency *= lacunarity;
                if skip && k % 3 == 1 {
                    continue;
                }
                let kept = octave_weight(h, lacunarity, k, frequency);
                let power = frequency.powf(-h);
                assert_eq!(
                    kept.to_bits(),
                    power.to_bits(),
                    "h {h}, lacunarity {lacunarity}, k {k}"
                );
            }
        }
    }
}
