//! Radiosity: the diffuse light a surface gathers from the others, sampled one path at a
//! time instead of through POV-Ray's irradiance cache.
//!
//! POV-Ray's rules, measured on a closed diffuse sphere lit from its centre (every pixel
//! (E + rho I)(1 + b rho + ... + (b rho)^R) for emission E, diffuse rho, light I,
//! brightness b, recursion_limit R): a surface adds its pigment times its diffuse value
//! times `brightness` times the cosine-weighted mean of the radiance over its hemisphere
//! (no 1/pi, like POV-Ray's diffuse term); what a radiosity ray sees is the full shading
//! of the surface it meets (lights, emission, its own gathering one bounce further,
//! reflection and refraction) but no highlights; radiosity rays count no trace level;
//! `no_radiosity` objects are invisible to them and they see the background. penumbra
//! traces one cosine-distributed ray per shading point, which is an unbiased estimate of
//! that mean (the cosine cancels against the density), and lets the lights be found by the
//! next event estimation each hit already does.

use glam::DVec3;

use super::{Integrator, Path, ROULETTE_MIN_Q, RayCounts, Shading};
use crate::geometry::{Ray, flags, offset_point};
use crate::render::dimensions::Purpose;
use crate::render::sampler::{PixelSampler, concentric_disc};
use crate::scene::{GREY_WEIGHTS, Radiosity};

/// What a surface's layers together reflect of the light radiosity gathers: over the
/// hemisphere on the viewer's side, and over the one behind (`diffuse front, back`: POV-Ray
/// gathers there too, measured: an emitting ball behind a plane of `diffuse 0, 1` lights it
/// 0.2503 where the ball's cosine-weighted share of the hemisphere is 0.25).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Albedo {
    pub front: DVec3,
    pub back: DVec3,
}

impl Integrator<'_> {
    /// The light the surface gathers: `albedo` times `brightness` times the radiance of one
    /// cosine-distributed radiosity ray. After the first bounce, roulette ends a path with
    /// the probability its albedo does not carry.
    pub(super) fn gathered(
        &self,
        s: &Shading,
        radiosity: &Radiosity,
        albedo: Albedo,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let block = s.path.block();
        let factors = Albedo {
            front: albedo.front * radiosity.brightness,
            back: albedo.back * radiosity.brightness,
        };
        let carried = factors.front.abs().max_element() + factors.back.abs().max_element();
        if carried == 0.0 {
            return DVec3::ZERO;
        }
        let q = if s.path.bounces == 0 || self.termination != super::Termination::Roulette {
            1.0
        } else {
            carried.clamp(ROULETTE_MIN_Q, 1.0)
        };
        if !self.survives(q, block, Purpose::DiffuseRoulette, sampler) {
            return DVec3::ZERO;
        }
        sampler.set_dimension(self.layout.dimension(block, Purpose::DiffuseDirection));
        let next = Path {
            level: s.path.level,
            weight: s.path.weight * carried / q,
            skip: flags::NO_RADIOSITY,
            interiors: s.path.interiors,
            wavelength: s.path.wavelength,
            bounces: s.path.bounces + 1,
        };
        let rays = if s.path.bounces == 0 && self.scene.output_gamma.is_some() {
            GAMMA_SCENE_RAYS
        } else {
            1
        };
        let gathered = if rays == 1 {
            self.radiosity_ray(s, radiosity, factors, next, sampler, counts)
        } else {
            let mut sum = DVec3::ZERO;
            for j in 0..rays {
                let mut sub = sampler.subsample(j, rays);
                sum += self.radiosity_ray(s, radiosity, factors, next, &mut sub, counts);
            }
            sum / f64::from(rays)
        };
        gathered / q
    }

    /// One cosine-distributed radiosity ray from the shaded point, times what the surface
    /// reflects of it: the side it leaves by is drawn in proportion to the two sides'
    /// `factors` and divided by that probability, reusing the direction's first coordinate
    /// (a surface with no back value reads exactly the values it did without the choice).
    fn radiosity_ray(
        &self,
        s: &Shading,
        radiosity: &Radiosity,
        factors: Albedo,
        mut next: Path,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let around = if radiosity.normal { s.n } else { s.facing };
        let (u, v) = sampler.get_2d();
        let front = factors.front.abs().max_element();
        let p_front = front / (front + factors.back.abs().max_element());
        let (around, factor, u) = if u < p_front {
            (around, factors.front / p_front, u / p_front)
        } else {
            next.interiors = super::crossing(s).2;
            let p_back = 1.0 - p_front;
            (-around, factors.back / p_back, (u - p_front) / p_back)
        };
        let dir = cosine_direction(around, (u, v));
        let origin = offset_point(s.surface.point, s.surface.normal, dir);
        counts.secondary += 1;
        let incoming = self.trace(&Ray::new(origin, dir), next, sampler, counts);
        factor * greyed(incoming, radiosity.gray_threshold)
    }
}

/// Radiosity rays per camera path's first diffuse bounce in a scene computed in gamma space
/// (`assumed_gamma` other than 1, or an old scene without it). POV-Ray decodes each traced
/// value, and its radiosity comes from a smooth cache, so what it decodes is nearly the
/// expectation; penumbra's one-ray estimate is noisy, and the decoding curve's bend turns
/// noise into brightness (E[x^2.2] > E[x]^2.2): animations/raddem (assumed_gamma 2.2) read
/// sqrt(B) 0.014 too bright against POV-Ray at any cache quality with one ray. Averaging
/// several rays before the decoding divides that bias by their number.
const GAMMA_SCENE_RAYS: u32 = 16;

/// A direction about the unit normal `n` with density cos(theta)/pi: a disc point lifted
/// to the hemisphere (Malley's method), which keeps the disc's strata.
fn cosine_direction(n: DVec3, u: (f64, f64)) -> DVec3 {
    let (x, y) = concentric_disc(u.0, u.1);
    let z = (1.0 - x * x - y * y).max(0.0).sqrt();
    let (a, b) = n.any_orthonormal_pair();
    a * x + b * y + n * z
}

/// `gray_threshold g`: the colour blended with its grey by g.
fn greyed(c: DVec3, g: f64) -> DVec3 {
    if g <= 0.0 {
        return c;
    }
    let grey = c.dot(DVec3::from_array(GREY_WEIGHTS));
    c * (1.0 - g) + DVec3::splat(grey * g)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cosine_directions_have_the_mean_cosine_of_two_thirds() {
        let n = DVec3::new(0.3, -0.5, 0.8).normalize();
        let k = 64;
        let mut sum = 0.0;
        for i in 0..k {
            for j in 0..k {
                let u = ((i as f64 + 0.5) / k as f64, (j as f64 + 0.5) / k as f64);
                let d = cosine_direction(n, u);
                assert!((d.length() - 1.0).abs() < 1e-9);
                assert!(d.dot(n) >= 0.0);
                sum += d.dot(n);
            }
        }
        let mean = sum / (k * k) as f64;
        // (The 64 x 64 midpoint grid itself is off by about 1e-3.)
        assert!((mean - 2.0 / 3.0).abs() < 3e-3, "{mean}");
    }

    #[test]
    fn grey_threshold_blends_towards_povrays_grey() {
        let c = DVec3::new(0.5, 0.25, 0.1);
        assert_eq!(greyed(c, 0.0), c);
        let g = greyed(c, 1.0);
        assert!(
            (g - DVec3::splat(0.30705)).abs().max_element() < 1e-4,
            "{g}"
        );
    }
}
