//! POV-Ray's `dispersion`: a refraction into a dispersing interior splits white light into
//! `dispersion_samples` wavelengths, each refracted at its own index of refraction and
//! carrying its own colour. Measured on POV-Ray 3.7 with an orthographic camera looking at
//! 40 degrees into a glass slab (ior 1.5) at a thin emissive strip inside it, one unit
//! deep: each wavelength's ray meets the strip from another pixel, so the image shows one
//! line per wavelength, whose position gives that wavelength's index by Snell's law and
//! whose colour is that wavelength's weight.
//!
//! - Wavelength i of n (0 the least refracted, red) has the index of refraction
//!   `ior * dispersion^((i + 0.5) / n - 0.5)` ([`interior_ior`]): the extreme samples lie
//!   half a step inside ior / sqrt(dispersion) .. ior * sqrt(dispersion), not at ior /
//!   dispersion and ior * dispersion. Dispersion 1.2, n = 7 measured 1.3873, 1.4242, 1.4615,
//!   1.5000, 1.5394, 1.5807, 1.6219 (the law: 1.3872, 1.4239, 1.4615, 1.5, 1.5396, 1.5803,
//!   1.6220); n = 2: 1.4331, 1.5692; n = 3: 1.4111, 1.5, 1.5945; n = 240 at dispersion 2:
//!   every line within 2e-3 of the law.
//! - Its colour is the integral over its stretch [i / n, (i + 1) / n] of a hue curve that is
//!   constant on 70 equal steps ([`HUE`], measured as the lines' colours at n = 240, where
//!   each step spans 3.4 lines and the lines inside one step have the same colour to half
//!   float precision). The curve reproduces n = 120 to 1.5e-5 and n = 2, 3, 7 to 2e-4: n = 7
//!   measured red 0.2571, 0.4167, 0.2708, 0.0098, 0, 0.0030, 0.0365, green 0, 0.1506,
//!   0.3787, 0.3611, 0.1095, 0, 0, blue 0, 0, 0, 0.0980, 0.3269, 0.3665, 0.2047. The
//!   weights of every n sum to (0.9938, 1.0000, 0.9962), not quite white, in POV-Ray too.
//! - Only refraction disperses. The reflection off a dispersing surface is traced once,
//!   white, and Fresnel's reflectivity takes the interior's own ior (measured: reflection
//!   0.5 and fresnel's 0.04575 at 40 degrees, the same at dispersion 1, 1.2 and 2).
//! - A ray disperses at the first dispersing refraction on its path and keeps its
//!   wavelength: leaving the glass through a parallel face it refracts at the same
//!   wavelength's index and comes out parallel (3 lines on a strip behind the slab, not 9,
//!   where that law puts them, to 3e-5), and entering another dispersing interior it refracts
//!   at that interior's index for the same (i + 0.5) / n, with the first interior's colour
//!   (ior 1.3 dispersion 1.5, 5 samples, behind ior 1.5 dispersion 1.2, 3 samples: three
//!   lines, to 1e-4 where that rule puts them).
//! - `dispersion 1` is no dispersion; fewer than 2 `dispersion_samples` is an error in
//!   POV-Ray ("Dispersion samples minimum is 2"); the default is 7.
//!
//! POV-Ray traces all n wavelengths; penumbra traces one per camera sample, drawn uniformly
//! with the stratified [`Purpose::Dispersion`] dimension and weighted by n times its colour,
//! which has POV-Ray's sum as its expectation.

use glam::DVec3;

use crate::render::dimensions::Purpose;
use crate::render::prepared::Material;
use crate::render::sampler::PixelSampler;

use super::optics::refract;
use super::{Branches, Integrator, Shading};

/// Steps of the hue curve.
const STEPS: usize = 70;

/// The hue curve: the colour per unit of the wavelength parameter (0 the least refracted),
/// on 70 equal steps, as measured (see the module documentation).
#[allow(clippy::approx_constant)] // Measured figures; one lies near log10(2) by chance.
const HUE: [[f64; 3]; STEPS] = [
    [0.6862, 0.0, 0.0],
    [0.9943, 0.0, 0.0],
    [1.2744, 0.0, 0.0],
    [1.5326, 0.0, 0.0],
    [1.7780, 0.0, 0.0],
    [1.9958, 0.0, 0.0],
    [2.1918, 0.0, 0.0],
    [2.3657, 0.0, 0.0],
    [2.5195, 0.0, 0.0],
    [2.6532, 0.0, 0.0],
    [2.7649, 0.0, 0.0],
    [2.8638, 0.1330, 0.0],
    [2.9260, 0.4340, 0.0],
    [2.9681, 0.7141, 0.0],
    [3.0029, 0.9796, 0.0],
    [3.0029, 1.2323, 0.0],
    [2.9883, 1.4557, 0.0],
    [2.9535, 1.6727, 0.0],
    [2.8912, 1.8768, 0.0],
    [2.8070, 2.0435, 0.0],
    [2.7100, 2.2119, 0.0],
    [2.5836, 2.3584, 0.0],
    [2.4426, 2.4774, 0.0],
    [2.2687, 2.5909, 0.0],
    [2.0856, 2.6880, 0.0],
    [1.8768, 2.7502, 0.0],
    [1.6516, 2.8217, 0.0],
    [1.3934, 2.8491, 0.0],
    [1.1197, 2.8766, 0.0],
    [0.8258, 2.8839, 0.0],
    [0.5109, 2.8693, 0.0],
    [0.1750, 2.8418, 0.0],
    [0.0, 2.7924, 0.0210],
    [0.0, 2.7301, 0.2870],
    [0.0, 2.6459, 0.5461],
    [0.0, 2.5488, 0.7768],
    [0.0, 2.4298, 1.0080],
    [0.0, 2.3035, 1.2177],
    [0.0, 2.1423, 1.4072],
    [0.0, 1.9812, 1.5958],
    [0.0, 1.7917, 1.7642],
    [0.0, 1.5894, 1.9189],
    [0.0, 1.3651, 2.0581],
    [0.0, 1.1270, 2.1844],
    [0.0, 0.8748, 2.2961],
    [0.0, 0.6020, 2.3932],
    [0.0, 0.3149, 2.4774],
    [0.0, 0.0, 2.5488],
    [0.0, 0.0, 2.6038],
    [0.0, 0.0, 2.6459],
    [0.0, 0.0, 2.6733],
    [0.0, 0.0, 2.6880],
    [0.0, 0.0, 2.6880],
    [0.0, 0.0, 2.6678],
    [0.0, 0.0, 2.6459],
    [0.0, 0.0, 2.5964],
    [0.0, 0.0, 2.5488],
    [0.0, 0.0, 2.4701],
    [0.0700, 0.0, 2.3877],
    [0.1400, 0.0, 2.2888],
    [0.2100, 0.0, 2.1698],
    [0.2520, 0.0, 2.0508],
    [0.2870, 0.0, 1.9043],
    [0.3081, 0.0, 1.7496],
    [0.3149, 0.0, 1.5820],
    [0.3010, 0.0, 1.3998],
    [0.2870, 0.0, 1.1966],
    [0.2520, 0.0, 0.9869],
    [0.2030, 0.0, 0.7631],
    [0.1400, 0.0, 0.5251],
];

/// The wavelength parameter of sample `i` of `n`, in (0, 1).
pub(super) fn wavelength(i: u32, n: u32) -> f64 {
    (f64::from(i) + 0.5) / f64::from(n)
}

/// The index of refraction of `material`'s interior for a ray of wavelength parameter
/// `wavelength` (`None`: a ray that has not dispersed, which sees the interior's own ior).
pub(super) fn interior_ior(material: &Material, wavelength: Option<f64>) -> f64 {
    let interior = &material.interior;
    match wavelength {
        Some(t) if interior.disperses() => interior.ior * interior.dispersion.powf(t - 0.5),
        _ => interior.ior,
    }
}

/// The hue curve's integral from 0 to `x`.
fn hue_integral(x: f64) -> DVec3 {
    let x = x.clamp(0.0, 1.0) * STEPS as f64;
    let whole = (x as usize).min(STEPS);
    let mut sum = HUE[..whole]
        .iter()
        .fold(DVec3::ZERO, |sum, h| sum + DVec3::from_array(*h));
    if whole < STEPS {
        sum += DVec3::from_array(HUE[whole]) * (x - whole as f64);
    }
    sum / STEPS as f64
}

/// The colour sample `i` of `n` carries.
pub fn sample_colour(i: u32, n: u32) -> DVec3 {
    let n = f64::from(n);
    hue_integral(f64::from(i + 1) / n) - hue_integral(f64::from(i) / n)
}

impl Integrator<'_> {
    /// The branches `b` after dispersion, and the wavelength the transmitted ray carries. A
    /// ray without a wavelength that refracts into or out of a dispersing interior takes one
    /// of its wavelengths, drawn uniformly, refracts at that wavelength's index and carries
    /// n times its colour; any other ray keeps its wavelength and its branches.
    pub(super) fn disperse(
        &self,
        s: &Shading,
        b: &Branches,
        sampler: &mut PixelSampler,
    ) -> (Branches, Option<f64>) {
        let interior = &s.material.interior;
        if s.path.wavelength.is_some() || !interior.disperses() || b.refracted.is_none() {
            return (*b, s.path.wavelength);
        }
        sampler.set_dimension(self.layout.dimension(s.path.block(), Purpose::Dispersion));
        let n = interior.dispersion_samples.max(1);
        let i = ((sampler.get_1d() * f64::from(n)) as u32).min(n - 1);
        let t = wavelength(i, n);
        let (from, to, beyond) = super::crossing_at(s, Some(t));
        let eta = from / to;
        let straight = (eta - 1.0).abs() < 1e-12;
        let refracted = if straight {
            Some(s.d)
        } else {
            refract(s.d, s.n, eta)
        };
        let dispersed = Branches {
            refracted,
            straight,
            beyond,
            transmit: b.transmit * sample_colour(i, n) * f64::from(n),
            ..*b
        };
        (dispersed, Some(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_weights_of_any_sample_count_sum_to_the_measured_near_white() {
        let measured = DVec3::new(0.9938, 1.0, 0.9962);
        for n in [2, 3, 7, 24, 240] {
            let sum = (0..n).fold(DVec3::ZERO, |s, i| s + sample_colour(i, n));
            assert!((sum - measured).abs().max_element() < 1e-4, "{n}: {sum}");
        }
    }

    #[test]
    fn the_weights_are_the_measured_ones() {
        // POV-Ray 3.7, dispersion_samples 7 and 2 (half-float EXR).
        let seven = [
            [0.25708, 0.0, 0.0],
            [0.41675, 0.15063, 0.0],
            [0.27075, 0.37866, 0.0],
            [0.0098, 0.36108, 0.09802],
            [0.0, 0.1095, 0.3269],
            [0.003, 0.0, 0.36646],
            [0.0365, 0.0, 0.20471],
        ];
        let two = [[0.9541, 0.72754, 0.0122], [0.03949, 0.27246, 0.98389]];
        for (n, table) in [(7, &seven[..]), (2, &two[..])] {
            for (i, w) in table.iter().enumerate() {
                let got = sample_colour(i as u32, n);
                let err = (got - DVec3::from_array(*w)).abs().max_element();
                assert!(err < 6e-4, "{n}/{i}: {got} against {w:?}");
            }
        }
    }

    #[test]
    fn the_samples_span_the_measured_indices() {
        let material = Material {
            texture: Default::default(),
            double_illuminate: false,
            light_group: None,
            inner: None,
            transmits: true,
            interior: crate::scene::Interior {
                ior: 1.5,
                dispersion: 1.2,
                ..Default::default()
            },
            interior_id: 0,
            hollow: false,
            photons: Default::default(),
            photon_shadow: false,
        };
        let measured = [1.3873, 1.4242, 1.4615, 1.5, 1.5394, 1.5807, 1.6219];
        for (i, m) in measured.iter().enumerate() {
            let ior = interior_ior(&material, Some(wavelength(i as u32, 7)));
            assert!((ior - m).abs() < 5e-4, "{i}: {ior} against {m}");
        }
        assert_eq!(interior_ior(&material, None), 1.5);
        let plain = Material {
            interior: crate::scene::Interior {
                ior: 1.5,
                ..Default::default()
            },
            ..material
        };
        assert_eq!(interior_ior(&plain, Some(0.1)), 1.5);
    }
}
