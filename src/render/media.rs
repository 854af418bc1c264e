//! Participating media made ready to render, with what POV-Ray computes for them, measured
//! on povray 3.7 (a slab 1 unit thick of a hollow `rgbt 1` box, seen head on against a
//! black or white emitting plane, `method 3` with 100 to 400 samples and `jitter 0`):
//!
//! - absorption a: what lies behind is multiplied by exp(-a d) per channel (0.6064 at
//!   a 0.5 and d 1; 0.3679 at d 2).
//! - emission e with absorption a: e (1 - exp(-a d)) / a is added (0.3801 at 400 samples
//!   against the integral's 0.3793; POV-Ray's adaptive quadrature overshoots with few:
//!   0.4819, 0.4460 and 0.3967 at 1, 5 and 20 samples).
//! - scattering s with `extinction` x takes out exp(-s x d) as absorption does.
//! - the light a scattering medium sends towards the viewer, per unit length, is s times
//!   the light's colour at the point times a phase function of the cosine c between the
//!   light's travel and the direction to the viewer, on POV-Ray's scale where isotropic
//!   scattering is 1 (a thin slab lit from behind: 1.0016 for type 1). The others, fitted
//!   over five angles and normalised by type 1's 1.0016: type 2 (Mie haze)
//!   0.5759 (1 + 9 ((1 + c) / 2)^8), type 3 (Mie murky) 0.494 (1 + 50 ((1 + c) / 2)^32)
//!   (0.4928 lit from behind, 0.4957 from the front: the fit holds to 0.6%),
//!   type 4 (Rayleigh) 0.7990 (1 + c^2), type 5 the Henyey-Greenstein function
//!   (1 - g^2) / (1 + g^2 - 2 g c)^1.5, averaging 1 (6.00 and 0.222 forward and back at g
//!   0.5).
//! - a density multiplies all three coefficients; its colour scales them per channel.

use glam::DVec3;

use crate::appearance::evaluate_pigment;
use crate::scene::{Media, Phase, Pigment, PigmentKind};

/// The coefficients of one medium, or of several added, at one point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Coefficients {
    /// What the medium takes out of a ray per unit length.
    pub extinction: DVec3,
    pub emission: DVec3,
}

#[derive(Clone, Debug)]
pub struct PreparedMedium {
    pub emission: DVec3,
    /// The scattering colour, zero for a medium that does not scatter.
    pub scattering: DVec3,
    extinction: DVec3,
    pub phase: Phase,
    densities: Vec<Pigment>,
    /// A bound of the largest density channel, for the transmittance estimator's step
    /// rate (which it needs for its variance only: the estimate is unbiased for any).
    density_bound: f64,
    /// Points per ray segment: POV-Ray's `intervals` times its minimum `samples`.
    pub points: u32,
}

/// Points per segment above this cost more than more camera samples would.
const MAX_POINTS: u32 = 64;

impl PreparedMedium {
    pub fn new(m: &Media) -> PreparedMedium {
        let s = &m.sampling;
        PreparedMedium {
            emission: m.emission,
            scattering: m.scattering.map_or(DVec3::ZERO, |s| s.colour),
            extinction: m.extinction(),
            phase: m
                .scattering
                .map_or(crate::scene::Phase::Isotropic, |s| s.phase),
            densities: m.densities.clone(),
            density_bound: m.densities.iter().map(pigment_bound).product(),
            points: (s.intervals * s.samples.0).clamp(1, MAX_POINTS),
        }
    }

    pub fn scatters(&self) -> bool {
        self.scattering != DVec3::ZERO
    }

    /// Whether the medium is the same everywhere.
    pub fn homogeneous(&self) -> bool {
        self.densities
            .iter()
            .all(|d| matches!(d.kind, PigmentKind::Solid(_)))
    }

    /// The density at `p`, per channel.
    pub fn density(&self, p: DVec3) -> DVec3 {
        self.densities
            .iter()
            .map(|d| evaluate_pigment(d, p).rgb)
            .product()
    }

    /// The largest extinction any point can have (any channel).
    pub fn extinction_bound(&self) -> f64 {
        self.extinction.abs().max_element() * self.density_bound
    }

    /// Extinction and emission at density `density`.
    pub fn coefficients(&self, density: DVec3) -> Coefficients {
        Coefficients {
            extinction: self.extinction * density,
            emission: self.emission * density,
        }
    }
}

/// The phase function on POV-Ray's scale, at cosine `c` between the light's direction of
/// travel and the direction towards the viewer.
pub fn phase(phase: Phase, c: f64) -> f64 {
    match phase {
        Phase::Isotropic => 1.0,
        Phase::MieHazy => 0.5759 * (1.0 + 9.0 * ((1.0 + c) / 2.0).powi(8)),
        Phase::MieMurky => 0.4940 * (1.0 + 50.0 * ((1.0 + c) / 2.0).powi(32)),
        Phase::Rayleigh => 0.7990 * (1.0 + c * c),
        Phase::HenyeyGreenstein(g) => (1.0 - g * g) / (1.0 + g * g - 2.0 * g * c).powf(1.5),
    }
}

/// The largest channel value a pigment can take anywhere (colour maps interpolate between
/// their entries, so their entries bound them).
fn pigment_bound(p: &Pigment) -> f64 {
    let colour = |c: &crate::scene::Colour| c.rgb.abs().max_element();
    match &p.kind {
        PigmentKind::Solid(c) => colour(c),
        PigmentKind::ColourMap { map, .. } => map.iter().map(|e| colour(&e.1)).fold(0.0, f64::max),
        PigmentKind::List { entries, .. } => entries.iter().map(pigment_bound).fold(0.0, f64::max),
        PigmentKind::PigmentMap { map, .. } => {
            map.iter().map(|e| pigment_bound(&e.1)).fold(0.0, f64::max)
        }
        PigmentKind::Image(_) => 1.0,
    }
}

/// The scene's media: the atmospheric ones, and those of each interior by interior id.
#[derive(Clone, Debug, Default)]
pub struct MediaTable {
    pub media: Vec<PreparedMedium>,
    /// How many of `media`, from the start, are atmospheric.
    atmospheric: usize,
    /// For each interior id, its range in `media`.
    by_interior: Vec<(u32, u32)>,
}

impl MediaTable {
    pub fn new(atmospheric: &[Media]) -> MediaTable {
        MediaTable {
            media: atmospheric.iter().map(PreparedMedium::new).collect(),
            atmospheric: atmospheric.len(),
            by_interior: Vec::new(),
        }
    }

    /// Records interior `id`'s media (once per interior).
    pub fn add_interior(&mut self, id: u32, media: &[Media]) {
        let id = id as usize;
        if self.by_interior.len() <= id {
            self.by_interior.resize(id + 1, (0, 0));
        }
        if self.by_interior[id].1 > self.by_interior[id].0 || media.is_empty() {
            return;
        }
        let start = self.media.len() as u32;
        self.media.extend(media.iter().map(PreparedMedium::new));
        self.by_interior[id] = (start, self.media.len() as u32);
    }

    pub fn is_empty(&self) -> bool {
        self.media.is_empty()
    }

    pub fn atmospheric(&self) -> std::ops::Range<u32> {
        0..self.atmospheric as u32
    }

    /// The media of interior `id`, as a range of indices into `media`.
    pub fn interior(&self, id: u32) -> std::ops::Range<u32> {
        self.by_interior
            .get(id as usize)
            .map_or(0..0, |&(a, b)| a..b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The average over the sphere of directions, as POV-Ray's scale sets it.
    fn mean(p: Phase) -> f64 {
        let n = 200_000;
        (0..n)
            .map(|i| phase(p, -1.0 + 2.0 * (i as f64 + 0.5) / n as f64))
            .sum::<f64>()
            / n as f64
    }

    #[test]
    fn henyey_greenstein_averages_one_and_isotropic_is_one() {
        assert_eq!(mean(Phase::Isotropic), 1.0);
        for g in [-0.6, 0.0, 0.3, 0.8] {
            let m = mean(Phase::HenyeyGreenstein(g));
            assert!((m - 1.0).abs() < 1e-3, "g {g}: {m}");
        }
    }

    #[test]
    fn phase_functions_match_povray_at_the_measured_angles() {
        // povray 3.7, each divided by type 1's figure in the same set-up: lit from behind
        // (c = 1) through a slab of scattering 0.1, where the integrand is constant (type 1:
        // 1.0016), and lit from the viewer's side (c = -1) through a slab of 0.002 (0.9995).
        let cases = [
            (Phase::MieHazy, 1.0, 0.57679 * 10.0 / 1.0016),
            (Phase::MieMurky, 1.0, 0.49354 * 51.0 / 1.0016),
            (Phase::Rayleigh, 1.0, 0.80029 * 2.0 / 1.0016),
            (Phase::MieHazy, -1.0, 0.5761 / 0.9995),
            (Phase::MieMurky, -1.0, 0.4955 / 0.9995),
            (Phase::Rayleigh, -1.0, 0.7985 * 2.0 / 0.9995),
            (Phase::HenyeyGreenstein(0.5), 1.0, 6.0),
            (Phase::HenyeyGreenstein(0.5), -1.0, 0.2222),
        ];
        for (p, c, want) in cases {
            let got = phase(p, c);
            // Type 3's two figures disagree with each other by 0.6%.
            assert!(
                (got / want - 1.0).abs() < 4e-3,
                "{p:?} at {c}: {got} vs {want}"
            );
        }
    }

    #[test]
    fn the_density_bound_covers_a_colour_map() {
        let m = Pigment {
            kind: PigmentKind::ColourMap {
                pattern: crate::scene::Pattern::new(crate::scene::PatternKind::Spherical),
                map: vec![
                    (0.0, crate::scene::Colour::rgb(0.0, 0.0, 0.0)),
                    (0.5, crate::scene::Colour::rgb(0.2, 2.5, 0.1)),
                    (1.0, crate::scene::Colour::rgb(1.0, 1.0, 1.0)),
                ],
            },
            ..Pigment::default()
        };
        assert_eq!(pigment_bound(&m), 2.5);
    }
}
