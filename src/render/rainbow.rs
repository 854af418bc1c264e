//! What POV-Ray's rainbows do to a ray segment, measured from povray 3.7 renders (a camera
//! looking along the rainbow's direction at a plain background, 16-bit linear output):
//!
//! - The index into the colour map is (theta - (angle - width / 2)) / width, theta the
//!   angle between the ray and `direction`; outside [0, 1] nothing shows (angle 20, width
//!   10: red 0.8457 = 1 - 0.1543 at theta 16.54 degrees, and so on across the ring).
//! - `jitter j` moves the index uniformly within +-j (j = 0.2: the deviations span
//!   -0.2000 to 0.1999, deciles at -0.162 and 0.161).
//! - Like a fog, with a = max(exp(-depth / distance), transmit), what lies behind, L,
//!   becomes L a (1 - f (1 - a) (1 - C)) + (1 - a) C for the colour C of filter f (matched
//!   to 4 digits on three rgbft colours; a fog's (1 - f + f C) misses by 0.17).
//! - `arc_angle A` (only if given) cuts the ring around `up`: at phi degrees from up the
//!   rainbow is weighted by smoothstep((A / 2 - phi) / (A / 2 - F / 2)) for
//!   `falloff_angle F` (F = A without it): 120 / 60 gives 0.5 at 45 degrees, 360 / 0 gives
//!   0.739 at 60 (smoothstep of 2/3: 0.741), 200 / 100 0.891 at 60 (0.896).

use glam::DVec3;

use crate::appearance::blend::{Blend, blend_position, mix};
use crate::render::fog::{FogEffect, Segment};
use crate::scene::{Colour, Rainbow};

/// The combined effect of the rainbows on one segment; `u` in [0, 1) drives the jitter.
pub fn rainbow_effect(rainbows: &[Rainbow], segment: &Segment, u: f64) -> FogEffect {
    let mut effect = FogEffect {
        factor: DVec3::ONE,
        added: DVec3::ZERO,
    };
    for r in rainbows {
        let Some((c, weight)) = seen(r, segment.direction, u) else {
            continue;
        };
        let depth = segment.length / r.distance;
        let a = (-depth).exp().max(c.transmit);
        let a = 1.0 - weight * (1.0 - a);
        let tint = DVec3::ONE - c.filter * (1.0 - a) * (DVec3::ONE - c.rgb);
        effect.factor *= a * tint;
        effect.added += (1.0 - a) * c.rgb;
    }
    effect
}

/// The colour the ray sees of one rainbow and the arc's weight there, if any.
fn seen(r: &Rainbow, d: DVec3, u: f64) -> Option<(Colour, f64)> {
    if r.width <= 0.0 || r.distance <= 0.0 || r.colour_map.is_empty() {
        return None;
    }
    let theta = d.dot(r.direction).clamp(-1.0, 1.0).acos().to_degrees();
    let index = (theta - (r.angle - r.width / 2.0)) / r.width + r.jitter * (2.0 * u - 1.0);
    if !(0.0..=1.0).contains(&index) {
        return None;
    }
    let weight = match r.arc {
        None => 1.0,
        Some((arc, falloff)) => arc_weight(r, d, arc, falloff),
    };
    if weight <= 0.0 {
        return None;
    }
    let map = &r.colour_map;
    let c = match blend_position(map, index, |e| e.0) {
        Blend::One(i) => map[i].1,
        Blend::Two(i, t) => mix(&map[i].1, &map[i + 1].1, t),
        Blend::None => return None,
    };
    Some((c, weight))
}

/// How much of the ring shows at direction `d`: 1 within the falloff angle of `up`, 0
/// past the arc's half angle, smoothstep between.
fn arc_weight(r: &Rainbow, d: DVec3, arc: f64, falloff: f64) -> f64 {
    let across = |v: DVec3| (v - v.dot(r.direction) * r.direction).normalize_or_zero();
    let phi = across(d)
        .dot(across(r.up))
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees();
    let (outer, inner) = (arc / 2.0, falloff.min(arc) / 2.0);
    if phi >= outer {
        return 0.0;
    }
    if phi <= inner {
        return 1.0;
    }
    let t = (outer - phi) / (outer - inner);
    t * t * (3.0 - 2.0 * t)
}

/// A number in [0, 1) for the jitter, fixed by the ray's direction (the same ray always
/// sees the same rainbow, whatever the thread).
pub fn jitter_number(d: DVec3) -> f64 {
    let mut h = d.x.to_bits() ^ d.y.to_bits().rotate_left(21) ^ d.z.to_bits().rotate_left(42);
    h ^= h >> 33;
    h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
    h ^= h >> 33;
    h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    h ^= h >> 33;
    (h >> 11) as f64 / (1u64 << 53) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(arc: Option<(f64, f64)>, colour: Colour) -> Rainbow {
        Rainbow {
            direction: DVec3::Z,
            angle: 20.0,
            width: 10.0,
            distance: 1e7,
            arc,
            colour_map: vec![(0.0, colour), (1.0, colour)],
            ..Rainbow::default()
        }
    }

    /// A ray `theta` degrees off the z axis, `phi` degrees from +y towards +x.
    fn ray(theta: f64, phi: f64) -> Segment {
        let (t, p) = (theta.to_radians(), phi.to_radians());
        Segment {
            origin: DVec3::ZERO,
            direction: DVec3::new(t.sin() * p.sin(), t.sin() * p.cos(), t.cos()),
            length: f64::INFINITY,
        }
    }

    #[test]
    fn filter_and_transmit_mix_as_povray_measured() {
        let behind = DVec3::new(0.2, 0.5, 0.8);
        // POV-Ray 3.7's pixels for three rainbow colours (rgb, filter, transmit).
        let measured = [
            ([1.0, 0.5, 0.0, 0.5, 0.3], [0.76, 0.4737, 0.156]),
            ([0.2, 0.8, 0.4, 1.0, 0.6], [0.1616, 0.596, 0.5248]),
            ([0.5, 0.1, 0.9, 0.3, 0.5], [0.3425, 0.2663, 0.844]),
        ];
        for ([r, g, b, f, t], expected) in measured {
            let c = Colour {
                rgb: DVec3::new(r, g, b),
                filter: f,
                transmit: t,
            };
            let seen = rainbow_effect(&[ring(None, c)], &ray(20.0, 0.0), 0.5).apply(behind);
            assert!(
                (seen - DVec3::from(expected)).abs().max_element() < 2e-4,
                "{seen}"
            );
        }
    }

    #[test]
    fn the_arc_fades_as_povray_measured() {
        let red = Colour::rgb(1.0, 0.0, 0.0);
        let red_at = |arc, phi| {
            rainbow_effect(&[ring(arc, red)], &ray(20.0, phi), 0.5)
                .apply(DVec3::ZERO)
                .x
        };
        // (arc_angle, falloff_angle, phi, POV-Ray's red over black)
        for (arc, falloff, phi, expected) in [
            (120.0, 60.0, 45.0, 0.5),
            (120.0, 60.0, 30.0, 1.0),
            (120.0, 60.0, 60.0, 0.0),
            (360.0, 0.0, 90.0, 0.5),
            (360.0, 0.0, 120.0, 0.261),
            (200.0, 100.0, 90.0, 0.104),
            (120.0, 120.0, 50.0, 1.0),
        ] {
            let got = red_at(Some((arc, falloff)), phi);
            assert!(
                (got - expected).abs() < 0.01,
                "{arc}/{falloff} at {phi}: {got}"
            );
        }
        assert_eq!(red_at(None, 170.0), 1.0);
        // Outside the ring nothing shows.
        let off = rainbow_effect(&[ring(None, red)], &ray(26.0, 0.0), 0.5);
        assert_eq!(off.apply(DVec3::ONE), DVec3::ONE);
    }
}
