//! What POV-Ray's fogs do to a ray segment, measured from povray 3.7 renders (one pixel, a
//! flat emitting plane at depth d behind the fog, 16-bit linear output):
//!
//! - One fog of colour C (rgb, filter f, transmit t): what lies behind, L, becomes
//!   `L a (1 - f + f C) + (1 - a) C` with `a = max(exp(-w / distance), t)`, where w is the
//!   depth through the fog (d for constant fog). The filter tints even at a small depth
//!   (d = 0.5, distance 20: matched to 4 digits).
//! - Several fogs: the factors multiply and the added colours add, whatever their order
//!   (two fogs, either order: 0.8095 0.4721 0.4093, matched).
//! - Ground fog: w is the integral of the density along the segment, density 1 up to
//!   fog_offset along `up` and 1 / (1 + u^2) above, u = (h - offset) / alt (measured on
//!   horizontal rays at u = 0.25, 0.5, 1, 2, 4: 0.941, 0.800, 0.500, 0.200, 0.0588; the
//!   docs' "25% at offset + alt" describes 1 / (1 + u)^2, which POV-Ray 3.7 does not do).
//! - Turbulence changes w, not the density: `w (1 - k min(1, turb_depth T))` with
//!   k = exp(-d / distance) for the segment's length d (not w: ground fog at distances 5,
//!   10 and 40 gives the same implied T only so) and T a fractal sum of noise read at the
//!   point turb_depth of the way along the segment, scaled by the turbulence vector.
//!   Measured on constant fog: at d = distance and at 2 distance the implied
//!   `turb_depth T` has the same quantiles; it scales with turb_depth (0.01, 0.25, 1) and
//!   clamps at 1; the turbulence amount changes only its scale in space. A ray that hits
//!   nothing has k = 0: its turbulence does nothing.

use glam::DVec3;

use crate::appearance::noise::fog_turbulence;
use crate::scene::{Fog, FogKind};

/// What the fogs do to the light behind a segment: multiply it, then add.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogEffect {
    pub factor: DVec3,
    pub added: DVec3,
}

impl FogEffect {
    pub fn apply(&self, behind: DVec3) -> DVec3 {
        behind * self.factor + self.added
    }
}

/// A segment of a ray: from `origin` along the unit `direction`, `length` long (infinite
/// for a ray that hits nothing).
#[derive(Clone, Copy, Debug)]
pub struct Segment {
    pub origin: DVec3,
    pub direction: DVec3,
    pub length: f64,
}

/// The combined effect of the fogs on one segment.
pub fn fog_effect(fogs: &[Fog], segment: &Segment) -> FogEffect {
    let mut effect = FogEffect {
        factor: DVec3::ONE,
        added: DVec3::ZERO,
    };
    for fog in fogs.iter().filter(|f| f.distance > 0.0) {
        let a = attenuation(fog, segment);
        let c = fog.colour;
        effect.factor *= a * (DVec3::splat(1.0 - c.filter) + c.filter * c.rgb);
        effect.added += (1.0 - a) * c.rgb;
    }
    effect
}

/// What reaches through the fogs from a light with `media_attenuation on`: each fog's
/// attenuation, with its filter term squared (measured: a light 10 units from a plane
/// through `rgbf <0.2, 0.5, 0.8, 0.5>` fog of distance 10 arrives as 0.1324 0.2069 0.2981
/// = exp(-1) (0.6, 0.75, 0.9)^2; `rgbt ... 0.6` as 0.6; plain colour as exp(-1)).
pub fn light_through_fog(fogs: &[Fog], segment: &Segment) -> DVec3 {
    fogs.iter()
        .filter(|f| f.distance > 0.0)
        .map(|fog| {
            let c = fog.colour;
            let tint = DVec3::splat(1.0 - c.filter) + c.filter * c.rgb;
            attenuation(fog, segment) * tint * tint
        })
        .product()
}

/// The fraction of what lies behind that one fog lets through (before its filter).
fn attenuation(fog: &Fog, segment: &Segment) -> f64 {
    let mut width = match fog.kind {
        FogKind::Constant => segment.length,
        FogKind::Ground { offset, alt } => ground_width(fog, segment, offset, alt),
    };
    if let Some(turb) = &fog.turbulence
        && width.is_finite()
        && segment.length.is_finite()
    {
        let k = (-segment.length / fog.distance).exp();
        let p = segment.origin + segment.direction * (segment.length * turb.depth);
        let q = fog.transform.inverse_point(p) * turb.turbulence.amount;
        let t = (turb.depth * fog_turbulence(q, &turb.turbulence)).min(1.0);
        width *= 1.0 - k * t;
    }
    (-width / fog.distance).exp().max(fog.colour.transmit)
}

/// The integral of the ground fog's density along the segment, in world units.
fn ground_width(fog: &Fog, segment: &Segment, offset: f64, alt: f64) -> f64 {
    let h0 = fog.up.dot(segment.origin);
    // Height gained per world unit along the ray.
    let slope = fog.up.dot(segment.direction);
    let density0 = ground_density(h0, offset, alt);
    if !segment.length.is_finite() {
        return if slope > 0.0 {
            (ground_integral(f64::INFINITY, offset, alt) - ground_integral(h0, offset, alt)) / slope
        } else if slope == 0.0 && density0 == 0.0 {
            0.0
        } else {
            f64::INFINITY
        };
    }
    let h1 = h0 + slope * segment.length;
    if (h1 - h0).abs() <= 1e-12 * (1.0 + h0.abs()) {
        return segment.length * density0;
    }
    segment.length * (ground_integral(h1, offset, alt) - ground_integral(h0, offset, alt))
        / (h1 - h0)
}

fn ground_density(h: f64, offset: f64, alt: f64) -> f64 {
    if h <= offset {
        1.0
    } else if alt > 0.0 {
        let u = (h - offset) / alt;
        1.0 / (1.0 + u * u)
    } else {
        0.0
    }
}

/// An antiderivative of the ground density in height: h below the offset, then
/// alt atan(u), which tends to alt pi / 2.
fn ground_integral(h: f64, offset: f64, alt: f64) -> f64 {
    if h <= offset {
        h
    } else if alt > 0.0 {
        offset + alt * ((h - offset) / alt).atan()
    } else {
        offset
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Colour;

    fn fog(distance: f64, rgb: [f64; 3], filter: f64, transmit: f64) -> Fog {
        Fog {
            distance,
            colour: Colour {
                rgb: DVec3::from(rgb),
                filter,
                transmit,
            },
            ..Fog::default()
        }
    }

    fn along_z(length: f64) -> Segment {
        Segment {
            origin: DVec3::ZERO,
            direction: DVec3::Z,
            length,
        }
    }

    fn close(a: DVec3, b: [f64; 3]) -> bool {
        (a - DVec3::from(b)).abs().max_element() < 1e-4
    }

    /// Figures read from povray's half-float EXR output (about 3e-4 at 0.3).
    fn close_half(a: DVec3, b: [f64; 3]) -> bool {
        (a - DVec3::from(b)).abs().max_element() < 3e-4
    }

    #[test]
    fn one_fog_matches_povray() {
        // povray: plane at depth 10 of colour (0.5, 0.7, 0.3), fog distance 20 colour
        // rgbft <0.2, 0.5, 0.8, 0.4, 0.1>: 0.2849 0.5364 0.4822; at depth 0.5: 0.3365
        // 0.5585 0.2889.
        let f = [fog(20.0, [0.2, 0.5, 0.8], 0.4, 0.1)];
        let behind = DVec3::new(0.5, 0.7, 0.3);
        assert!(close(
            fog_effect(&f, &along_z(10.0)).apply(behind),
            [0.2849, 0.5364, 0.4822]
        ));
        assert!(close(
            fog_effect(&f, &along_z(0.5)).apply(behind),
            [0.3365, 0.5585, 0.2889]
        ));
        // Transmit is the least that shows: the background (infinite depth) behind
        // rgbft <0.2, 0.5, 0.8, 0.5, 0.3> reads 0.32 0.575 0.83 on white, 0.14 0.35 0.56
        // on black.
        let f = [fog(20.0, [0.2, 0.5, 0.8], 0.5, 0.3)];
        let e = fog_effect(&f, &along_z(f64::INFINITY));
        assert!(close(e.apply(DVec3::ONE), [0.32, 0.575, 0.83]));
        assert!(close(e.apply(DVec3::ZERO), [0.14, 0.35, 0.56]));
    }

    #[test]
    fn fogs_combine_in_any_order_as_povray() {
        let a = fog(20.0, [0.2, 0.5, 0.8], 0.4, 0.1);
        let b = fog(7.0, [0.9, 0.3, 0.1], 0.6, 0.2);
        let behind = DVec3::new(0.5, 0.7, 0.3);
        let ab = fog_effect(&[a.clone(), b.clone()], &along_z(10.0)).apply(behind);
        let ba = fog_effect(&[b, a], &along_z(10.0)).apply(behind);
        assert!(close(ab, [0.8095, 0.4721, 0.4093]) && close(ba, [0.8095, 0.4721, 0.4093]));
    }

    #[test]
    fn lights_dim_through_fog_as_povray() {
        let at = |f: Fog, d: f64| light_through_fog(&[f], &along_z(d));
        let filtered = at(fog(10.0, [0.2, 0.5, 0.8], 0.5, 0.0), 10.0);
        assert!(close_half(filtered, [0.1324, 0.2069, 0.2981]), "{filtered}");
        assert!(close_half(
            at(fog(10.0, [0.2, 0.5, 0.8], 0.0, 0.6), 10.0),
            [0.6001; 3]
        ));
        let far = at(fog(10.0, [0.2, 0.5, 0.8], 0.0, 0.0), 20.0);
        assert!(close_half(far, [0.1354; 3]), "{far}");
    }

    #[test]
    fn ground_fog_integrates_its_density() {
        let g = Fog {
            kind: FogKind::Ground {
                offset: 1.0,
                alt: 2.0,
            },
            ..fog(10.0, [1.0; 3], 0.0, 0.0)
        };
        // Horizontal below the offset: constant fog.
        let low = Segment {
            origin: DVec3::new(0.0, 0.5, 0.0),
            direction: DVec3::Z,
            length: 10.0,
        };
        assert!((ground_width(&g, &low, 1.0, 2.0) - 10.0).abs() < 1e-12);
        // Horizontal at offset + alt: half the density (povray: 0.500).
        let high = Segment {
            origin: DVec3::new(0.0, 3.0, 0.0),
            ..low
        };
        assert!((ground_width(&g, &high, 1.0, 2.0) - 5.0).abs() < 1e-12);
        // Straight up from the ground to infinity: 1 (below the offset) + alt pi / 2.
        let up = Segment {
            origin: DVec3::ZERO,
            direction: DVec3::Y,
            length: f64::INFINITY,
        };
        let expected = 1.0 + std::f64::consts::PI;
        assert!((ground_width(&g, &up, 1.0, 2.0) - expected).abs() < 1e-12);
        // A slanted segment against a numerical integral of the density.
        let dir = DVec3::new(0.6, 0.8, 0.0);
        let s = Segment {
            origin: DVec3::new(0.0, -1.0, 0.0),
            direction: dir,
            length: 9.0,
        };
        let n = 100_000;
        let numeric: f64 = (0..n)
            .map(|i| {
                let t = (f64::from(i) + 0.5) * 9.0 / f64::from(n);
                ground_density(-1.0 + 0.8 * t, 1.0, 2.0) * 9.0 / f64::from(n)
            })
            .sum();
        assert!((ground_width(&g, &s, 1.0, 2.0) - numeric).abs() < 1e-6);
    }
}
