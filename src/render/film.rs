//! The film keeps per-pixel sums, not averages, so that renders of disjoint sample ranges
//! merge by addition. Sums are 64-bit fixed point: integer addition is associative, so the
//! merged sums equal the single-run sums bit for bit, whatever the split.

/// Fixed-point scale: 2^-24 (6e-8) resolution per sample, sums up to 5e11.
const SCALE: f64 = (1u64 << 24) as f64;

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PixelSum {
    pub rgb: [i64; 3],
    pub count: u32,
}

impl PixelSum {
    /// Adds one sample (linear radiance). Non-finite samples must be filtered by the caller.
    #[inline]
    pub fn add(&mut self, rgb: [f64; 3]) {
        for (s, v) in self.rgb.iter_mut().zip(rgb) {
            *s = s.saturating_add((v * SCALE).round() as i64);
        }
        self.count += 1;
    }

    pub fn merge(&mut self, other: &PixelSum) {
        for (s, o) in self.rgb.iter_mut().zip(other.rgb) {
            *s = s.saturating_add(o);
        }
        self.count += other.count;
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
            pixels: vec![PixelSum::default(); width * height],
            non_finite: Vec::new(),
        }
    }

    /// Adds another film of the same size (another sample range of the same render).
    pub fn merge(&mut self, other: &Film) {
        assert_eq!((self.width, self.height), (other.width, other.height));
        for (a, b) in self.pixels.iter_mut().zip(&other.pixels) {
            a.merge(b);
        }
        self.non_finite.extend_from_slice(&other.non_finite);
    }

    /// Mean radiance per pixel, row-major, top row first.
    pub fn means(&self) -> Vec<[f32; 3]> {
        self.pixels
            .iter()
            .map(|p| p.mean().map(|v| v as f32))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
