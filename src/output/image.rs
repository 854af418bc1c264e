/// A linear RGB image, row-major with the top row first (POV-Ray's and PNG's order).
///
/// Pixels are `f32` because that is what the film resolves to and what EXR stores; anything
/// that sums many pixels (block means, statistics) accumulates in `f64` itself.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<[f32; 3]>,
}

impl Image {
    /// A black image.
    pub fn new(width: usize, height: usize) -> Image {
        Image::filled(width, height, [0.0; 3])
    }

    pub fn filled(width: usize, height: usize, colour: [f32; 3]) -> Image {
        Image {
            width,
            height,
            pixels: vec![colour; width * height],
        }
    }

    /// Wraps existing pixels; `None` when their count does not match the size, so a caller
    /// assembling pixels from a file or a film cannot build an inconsistent image.
    pub fn from_pixels(width: usize, height: usize, pixels: Vec<[f32; 3]>) -> Option<Image> {
        (width.checked_mul(height) == Some(pixels.len())).then_some(Image {
            width,
            height,
            pixels,
        })
    }

    /// Builds an image by evaluating `f(x, y)` at every pixel.
    pub fn from_fn(
        width: usize,
        height: usize,
        mut f: impl FnMut(usize, usize) -> [f32; 3],
    ) -> Image {
        let mut pixels = Vec::with_capacity(width * height);
        for y in 0..height {
            for x in 0..width {
                pixels.push(f(x, y));
            }
        }
        Image {
            width,
            height,
            pixels,
        }
    }

    /// Panics when (x, y) lies outside the image, like slice indexing: a caller bug.
    pub fn get(&self, x: usize, y: usize) -> [f32; 3] {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside image"
        );
        self.pixels[y * self.width + x]
    }

    /// Panics when (x, y) lies outside the image, like slice indexing: a caller bug.
    pub fn set(&mut self, x: usize, y: usize, colour: [f32; 3]) {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside image"
        );
        self.pixels[y * self.width + x] = colour;
    }

    pub fn same_size(&self, other: &Image) -> bool {
        self.width == other.width && self.height == other.height
    }

    pub fn is_empty(&self) -> bool {
        self.pixels.is_empty()
    }

    /// Applies `f` to every channel value.
    pub fn map(&self, mut f: impl FnMut(f32) -> f32) -> Image {
        Image {
            width: self.width,
            height: self.height,
            pixels: self
                .pixels
                .iter()
                .map(|p| [f(p[0]), f(p[1]), f(p[2])])
                .collect(),
        }
    }

    /// Positions (x, y, channel) of NaN or infinite values, in pixel order.
    pub fn non_finite(&self) -> Vec<(usize, usize, usize)> {
        let mut found = Vec::new();
        for (i, p) in self.pixels.iter().enumerate() {
            for (c, v) in p.iter().enumerate() {
                if !v.is_finite() {
                    found.push((i % self.width, i / self.width, c));
                }
            }
        }
        found
    }

    /// Averages each `factor` x `factor` block into one pixel: an exact box filter, which is
    /// how a supersampled POV-Ray render becomes a converged reference. Accumulates in `f64`
    /// so that 256 half-float samples per pixel lose nothing to summation. `None` when the
    /// size is not a multiple of `factor` or `factor` is 0.
    pub fn downsample(&self, factor: usize) -> Option<Image> {
        if factor == 0 || !self.width.is_multiple_of(factor) || !self.height.is_multiple_of(factor)
        {
            return None;
        }
        let (w, h) = (self.width / factor, self.height / factor);
        let scale = 1.0 / (factor * factor) as f64;
        let mut out = Image::new(w, h);
        for by in 0..h {
            for bx in 0..w {
                let mut sum = [0.0f64; 3];
                for y in by * factor..(by + 1) * factor {
                    let row = &self.pixels[y * self.width + bx * factor..][..factor];
                    for p in row {
                        for c in 0..3 {
                            sum[c] += f64::from(p[c]);
                        }
                    }
                }
                out.pixels[by * w + bx] = sum.map(|s| (s * scale) as f32);
            }
        }
        Some(out)
    }
}
