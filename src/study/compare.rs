//! `penumbra compare`: how far images are from a reference, and, given replicates, how much
//! of that distance is noise and how much is bias.
//!
//! One image's RMSE mixes noise with bias and cannot say which; with two or more replicates
//! (independent renders of the same scene) the split of `metrics` applies: the noise sqrt(V)
//! from replicate differences and the noise-free bias sqrt(B) from products of independent
//! errors on 4x4 block means.

use super::metrics::{self, Bias, ImageDifference, TileReport};
use super::{StudyError, charts};
use crate::output::{Image, read_exr, read_image};
use std::fmt;
use std::path::Path;

/// Added to the reference's square in relMSE's denominator, so that black pixels do not
/// dominate (pbrt's and most papers' choice).
pub const REL_MSE_EPSILON: f64 = 0.01;

/// An image to compare against, with its k/2 companion when it is a penumbra reference.
#[derive(Debug, Clone, PartialEq)]
pub struct Target {
    pub image: Image,
    /// r_k/2; without it the reference's own error cannot be subtracted from B.
    pub half: Option<Image>,
}

/// Reads an EXR (linear) or PNG (decoded from sRGB); an EXR's `half` layer is kept.
pub fn read_target(path: &Path) -> Result<Target, StudyError> {
    let is_exr = path
        .extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("exr"));
    if is_exr {
        let file = read_exr(path)?;
        let half = file.layer("half").cloned();
        Ok(Target {
            image: file.image,
            half,
        })
    } else {
        Ok(Target {
            image: read_image(path)?,
            half: None,
        })
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// The first image against the reference.
    pub difference: ImageDifference,
    pub rel_mse: f64,
    /// Present with two or more images.
    pub split: Option<Split>,
}

/// The bias and noise split over replicates.
#[derive(Debug, Clone, PartialEq)]
pub struct Split {
    pub replicates: usize,
    /// Mean over replicates of each one's RMSE against the reference.
    pub mean_rmse: f64,
    /// sqrt(V): one replicate's per-pixel noise.
    pub sqrt_v: f64,
    pub bias: Bias,
    /// Whether r - r_k/2 was subtracted (the reference carried its k/2 companion).
    pub reference_term_subtracted: bool,
    pub tiles: TileReport,
}

/// mean over pixels and channels of (a - r)^2 / (r^2 + `REL_MSE_EPSILON`).
pub fn rel_mse(a: &Image, reference: &Image) -> Result<f64, StudyError> {
    metrics::compare(a, reference)?;
    let sum: f64 = a
        .pixels
        .iter()
        .zip(&reference.pixels)
        .flat_map(|(p, q)| {
            (0..3).map(move |c| {
                let (x, r) = (f64::from(p[c]), f64::from(q[c]));
                (x - r) * (x - r) / (r * r + REL_MSE_EPSILON)
            })
        })
        .sum();
    Ok(sum / (a.pixels.len() * 3) as f64)
}

/// Compares `images[0]` with the reference and, when there are several images, splits the
/// error of the set into bias and noise.
pub fn compare_to(images: &[Image], reference: &Target) -> Result<Comparison, StudyError> {
    let first = images
        .first()
        .ok_or(StudyError::TooFewReplicates { found: 0 })?;
    for (what, image) in std::iter::once(("the reference", &reference.image)).chain(
        reference
            .half
            .iter()
            .map(|h| ("the reference's half layer", h)),
    ) {
        if !image.same_size(first) {
            return Err(StudyError::SizeMismatch {
                what: what.into(),
                expected: (first.width, first.height),
                found: (image.width, image.height),
            });
        }
    }
    let difference = metrics::compare(first, &reference.image)?;
    let rel_mse = rel_mse(first, &reference.image)?;
    let split = if images.len() >= 2 {
        // Without a k/2 render the reference stands in for it: r - r = 0, nothing subtracted.
        let half = reference.half.as_ref().unwrap_or(&reference.image);
        let mut total = 0.0;
        for image in images {
            total += metrics::rmse(image, &reference.image)?;
        }
        Some(Split {
            replicates: images.len(),
            mean_rmse: total / images.len() as f64,
            sqrt_v: metrics::noise_variance(images)?.max(0.0).sqrt(),
            bias: metrics::bias_estimate(images, &reference.image, half)?,
            reference_term_subtracted: reference.half.is_some(),
            tiles: metrics::tile_test(images, &reference.image, half)?,
        })
    } else {
        None
    };
    Ok(Comparison {
        difference,
        rel_mse,
        split,
    })
}

impl fmt::Display for Comparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let d = &self.difference;
        writeln!(
            f,
            "RMSE {:.6}  relMSE {:.6}  mean abs {:.6}  max abs {:.6} at ({}, {}) channel {}",
            d.rmse, self.rel_mse, d.mean_abs, d.max_abs, d.max_at.0, d.max_at.1, d.max_at.2
        )?;
        if let Some(s) = &self.split {
            writeln!(
                f,
                "{} replicates: mean RMSE {:.6}  noise sqrt(V) {:.6}  bias sqrt(B) {:.6} \
                 (B = {:.3e}: cross term {:.3e} - reference term {:.3e}{})",
                s.replicates,
                s.mean_rmse,
                s.sqrt_v,
                s.bias.sqrt_b(),
                s.bias.b,
                s.bias.cross,
                s.bias.reference_term,
                if s.reference_term_subtracted {
                    ""
                } else {
                    "; no k/2 layer, so the reference's own error is not subtracted"
                }
            )?;
            writeln!(
                f,
                "tile test: {} of {} (8x8 tile, channel) pairs fail",
                s.tiles.failed(),
                s.tiles.tested
            )?;
        }
        Ok(())
    }
}

/// The colour scale for a difference image: the 99th percentile of |mean difference|, so
/// that a few outliers do not wash out the rest. Never zero.
pub fn default_diff_scale(a: &Image, b: &Image) -> f64 {
    let mut values: Vec<f64> = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(p, q)| {
            ((0..3)
                .map(|c| f64::from(p[c]) - f64::from(q[c]))
                .sum::<f64>()
                / 3.0)
                .abs()
        })
        .filter(|v| v.is_finite())
        .collect();
    if values.is_empty() {
        return 1.0;
    }
    values.sort_by(f64::total_cmp);
    let p99 = values[((values.len() - 1) as f64 * 0.99).round() as usize];
    if p99 > 0.0 { p99 } else { 1e-3 }
}

/// The mean of the images, pixel by pixel: with replicates the difference image should show
/// bias, not one replicate's noise.
pub fn mean_image(images: &[Image]) -> Result<Image, StudyError> {
    let first = images
        .first()
        .ok_or(StudyError::TooFewReplicates { found: 0 })?;
    let mut sum = vec![[0.0f64; 3]; first.pixels.len()];
    for (k, image) in images.iter().enumerate() {
        if !image.same_size(first) {
            return Err(StudyError::SizeMismatch {
                what: format!("image {}", k + 1),
                expected: (first.width, first.height),
                found: (image.width, image.height),
            });
        }
        for (s, p) in sum.iter_mut().zip(&image.pixels) {
            for c in 0..3 {
                s[c] += f64::from(p[c]);
            }
        }
    }
    let n = images.len() as f64;
    let pixels = sum.into_iter().map(|s| s.map(|v| (v / n) as f32)).collect();
    Image::from_pixels(first.width, first.height, pixels).ok_or(StudyError::InvalidImage {
        what: "mean image".into(),
    })
}

/// Writes the signed difference (mean of `images`) - reference; returns the scale used.
pub fn write_diff(
    path: &Path,
    images: &[Image],
    reference: &Image,
    scale: Option<f64>,
) -> Result<f64, StudyError> {
    let mean = mean_image(images)?;
    metrics::compare(&mean, reference)?;
    let scale = match scale {
        Some(s) if s > 0.0 && s.is_finite() => s,
        Some(s) => {
            return Err(StudyError::InvalidRequest(format!(
                "difference scale {s} must be positive"
            )));
        }
        None => default_diff_scale(&mean, reference),
    };
    charts::write_difference_png(path, &mean, reference, scale)?;
    Ok(scale)
}
