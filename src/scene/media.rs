//! `media { }`: participating media, in an object's interior or filling the atmosphere.
//! The coefficients are per unit length; a medium's `density` blocks scale all of them.

use glam::DVec3;

use super::{Pigment, Transform};

/// How a scattering medium sends light on, by the angle between the light's travel and the
/// direction it leaves in. POV-Ray's scale is its own: isotropic scattering is 1 (not
/// 1 / 4 pi), and the others carry the constants measured for them (render::media).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Phase {
    /// Type 1.
    Isotropic,
    /// Type 2, Mie scattering in haze.
    MieHazy,
    /// Type 3, Mie scattering in murky air.
    MieMurky,
    /// Type 4.
    Rayleigh,
    /// Type 5, with `eccentricity` g in (-1, 1): forward scattering for g > 0.
    HenyeyGreenstein(f64),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scattering {
    pub phase: Phase,
    pub colour: DVec3,
    /// How much of the scattering also takes light out of the ray (`extinction`, 1).
    pub extinction: f64,
}

/// POV-Ray's quadrature settings. penumbra reads them; its own estimator is unbiased for
/// the integral these approximate, and takes `intervals * samples.0` points per ray segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MediaSampling {
    pub method: u32,
    pub intervals: u32,
    pub samples: (u32, u32),
    pub confidence: f64,
    pub variance: f64,
    pub ratio: f64,
    pub jitter: f64,
    pub aa_level: u32,
    pub aa_threshold: f64,
}

impl Default for MediaSampling {
    fn default() -> Self {
        MediaSampling {
            method: 3,
            intervals: 1,
            samples: (1, 1),
            confidence: 0.9,
            variance: 1.0 / 128.0,
            ratio: 0.9,
            jitter: 0.0,
            aa_level: 3,
            aa_threshold: 0.1,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Default)]
pub struct Media {
    pub absorption: DVec3,
    pub emission: DVec3,
    pub scattering: Option<Scattering>,
    /// Multiplied together (measured: `density { rgb 0.5 } density { rgb <1, .5, .2> }`
    /// emits 0.5 0.25 0.1); none means 1 everywhere. Their pigments' transforms include
    /// the media's and the object's.
    pub densities: Vec<Pigment>,
    pub sampling: MediaSampling,
}

impl Media {
    pub fn transform_by(&mut self, t: &Transform) {
        for d in &mut self.densities {
            d.transform_by(t);
        }
    }

    /// The light it takes out of a ray per unit length, at density 1.
    pub fn extinction(&self) -> DVec3 {
        self.absorption
            + self
                .scattering
                .map_or(DVec3::ZERO, |s| s.colour * s.extinction)
    }
}
