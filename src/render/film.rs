//! The film keeps per-pixel sums, not averages, so that renders of disjoint sample ranges
//! merge by addition. Sums are 64-bit fixed point: integer addition is associative, so the
//! merged sums equal the single-run sums bit for bit, whatever the split. The sums of
//! squares are the squares of the same fixed-point samples, in 128 bits, so the variance
//! a merged film reports is exactly the single run's too.

use rayon::prelude::*;

/// Fixed-point scale: 2^-24 (6e-8) resolution per sample, sums up to 5e11.
const SCALE: f64 = (1u64 << 24) as f64;

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PixelSum {
    pub rgb: [i64; 3],
    pub count: u32,
    /// Sums of the squared fixed-point samples (scale 2^48).
    pub squares: [u128; 3],
}

impl PixelSum {
    /// Adds one sample (linear radiance). Non-finite samples must be filtered by the caller.
    #[inline]
    pub fn add(&mut self, rgb: [f64; 3]) {
        for ((sum, square), v) in self.rgb.iter_mut().zip(&mut self.squares).zip(rgb) {
            let q = to_fixed(v * SCALE);
            *sum = sum.saturating_add(q);
            *square = square.saturating_add(u128::from(q.unsigned_abs()).pow(2));
        }
        self.count += 1;
    }

    pub fn merge(&mut self, other: &PixelSum) {
        for c in 0..3 {
            self.rgb[c] = self.rgb[c].saturating_add(other.rgb[c]);
            self.squares[c] = self.squares[c].saturating_add(other.squares[c]);
        }
        self.count += other.count;
    }

    /// The variance of this pixel's mean, per channel: the samples' unbiased variance over
    /// the count (0 with fewer than two samples).
    pub fn variance_of_mean(&self) -> [f64; 3] {
        if self.count < 2 {
            return [0.0; 3];
        }
        let n = f64::from(self.count);
        std::array::from_fn(|c| {
            let sum = self.rgb[c] as f64 / SCALE;
            let squares = self.squares[c] as f64 / (SCALE * SCALE);
            ((squares - sum * sum / n) / (n - 1.0)).max(0.0) / n
        })
    }

    pub fn mean(&self) -> [f64; 3] {
        if self.count == 0 {
            return [0.0; 3];
        }
        let n = self.count as f64 * SCALE;
        self.rgb.map(|s| s as f64 / n)
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<PixelSum>,
    /// Samples that came out NaN or infinite, zeroed and listed with their pixel (x, y).
    pub non_finite: Vec<(u32, u32)>,
}

impl Film {
    pub fn new(width: usize, height: usize) -> Film {
        Film {
            width,
            height,
            pixels: filled(PixelSum::default(), width * height),
            non_finite: Vec::new(),
        }
    }

    /// Adds another film of the same size (another sample range of the same render). The
    /// non-finite list is kept sorted, so it too is the same whatever the split.
    pub fn merge(&mut self, other: &Film) {
        assert_eq!((self.width, self.height), (other.width, other.height));
        for (a, b) in self.pixels.iter_mut().zip(&other.pixels) {
            a.merge(b);
        }
        self.non_finite.extend_from_slice(&other.non_finite);
        self.non_finite.sort_unstable_by_key(|&(x, y)| (y, x));
    }

    /// Samples the film holds, over all pixels.
    pub fn samples(&self) -> u64 {
        self.pixels.iter().map(|p| u64::from(p.count)).sum()
    }

    /// Mean radiance per pixel, row-major, top row first.
    pub fn means(&self) -> Vec<[f32; 3]> {
        self.pixels
            .iter()
            .map(|p| p.mean().map(|v| v as f32))
            .collect()
    }
}

/// `n` copies of `value`, written in parallel: a 640x480 film is 25 MB, and its first
/// touch (6,000 page faults, about 10 ms of a 0.14 s one-sample render) is shared out
/// over the render's threads.
pub fn filled<T: Clone + Send>(value: T, n: usize) -> Vec<T> {
    let mut v = Vec::with_capacity(n);
    v.par_extend(rayon::iter::repeat_n(value, n));
    v
}

/// `x.round() as i64` (halves away from zero) without calling `round`, a library function on
/// processors without SSE4.1 (3.5% of an empty scene's render): the truncation `as i64` is
/// exact, and so is the fraction it leaves below 2^52, where every double is whole.
fn to_fixed(x: f64) -> i64 {
    if x.is_nan() || x.abs() >= 4_503_599_627_370_496.0 {
        return x as i64;
    }
    let t = x as i64;
    let fraction = x - t as f64;
    t + i64::from(fraction >= 0.5) - i64::from(fraction <= -0.5)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_point_rounds_as_round_does() {
        use rand::RngExt;
        let mut rng = rand_pcg::Pcg32::new(7, 9);
        let edges = [
            0.5,
            -0.5,
            1.5,
            -2.5,
            0.499_999_999_999_999_94,
            4_503_599_627_370_495.5,
        ];
        let huge = [
            1e300,
            -1e300,
            f64::MAX,
            9.3e18,
            -9.3e18,
            0.0,
            -0.0,
            f64::NAN,
        ];
        let random = (0..100_000).map(|_| {
            let (m, e) = (rng.random::<f64>() - 0.5, rng.random_range(-8..60));
            m * 2f64.powi(e)
        });
        for x in edges.into_iter().chain(huge).chain(random) {
            assert_eq!(to_fixed(x), x.round() as i64, "{x}");
        }
    }

    #[test]
    fn split_sums_merge_exactly() {
        let samples: Vec<[f64; 3]> = (0..100)
            .map(|i| {
                let x = (i as f64 * 0.7371).sin().abs() * 3.0;
                [x, x * 0.1, 1.0 / (1.0 + x)]
            })
            .collect();
        let mut whole = PixelSum::default();
        samples.iter().for_each(|s| whole.add(*s));
        let mut a = PixelSum::default();
        let mut b = PixelSum::default();
        samples[..37].iter().for_each(|s| a.add(*s));
        samples[37..].iter().for_each(|s| b.add(*s));
        a.merge(&b);
        assert_eq!(a, whole);
        let mean: f64 = samples.iter().map(|s| s[0]).sum::<f64>() / 100.0;
        assert!((whole.mean()[0] - mean).abs() < 1e-7);
    }
}
