use glam::DVec3;

use super::blend::{Blend, blend_position, mix};
use super::pattern::{pattern_index, pattern_value_at, warp_chain};
use std::f64::consts::{PI, TAU};

use crate::geometry::TexturePoint;
use crate::scene::{Colour, ImageMap, MapType, PatternKind, Pigment, PigmentKind};

/// The pigment's colour at a point: a world-space point, or a surface point that also
/// carries the surface's (u, v) for pigments with `uv_mapping`.
pub fn evaluate_pigment(pigment: &Pigment, at: impl Into<TexturePoint>) -> Colour {
    let at = at.into();
    pigment_at(pigment, at)
}

/// `average pigment_map { [w1 P1] [w2 P2] ... }`: (w1 P1 + w2 P2 + ...) / (w1 + w2 + ...),
/// every channel (filter and transmit too).
fn average(map: &[(f64, Pigment)], at: TexturePoint) -> Colour {
    let total: f64 = map.iter().map(|e| e.0).sum();
    if map.is_empty() || total == 0.0 {
        return Colour::BLACK;
    }
    let mut sum = Colour::BLACK;
    for (w, p) in map {
        let c = pigment_at(p, at);
        sum.rgb += c.rgb * *w;
        sum.filter += c.filter * w;
        sum.transmit += c.transmit * w;
    }
    Colour {
        rgb: sum.rgb / total,
        filter: sum.filter / total,
        transmit: sum.transmit / total,
    }
}

fn pigment_at(pigment: &Pigment, mut at: TexturePoint) -> Colour {
    // A uv-mapped pigment and everything inside it see the point (u, v, 0).
    if pigment.uv_mapping {
        at.world = at.uv.extend(0.0);
    }
    let world = at.world;
    match &pigment.kind {
        PigmentKind::Solid(c) => *c,
        PigmentKind::List { pattern, entries } => {
            if entries.is_empty() {
                return Colour::BLACK;
            }
            let p = pigment.transform.inverse_point(world);
            let index = pattern_index(pattern, p).min(entries.len() - 1);
            pigment_at(&entries[index], at)
        }
        PigmentKind::ColourMap { pattern, map } => {
            let p = pigment.transform.inverse_point(world);
            let v = pattern_value_at(pattern, p, at.normal);
            match blend_position(map, v, |e| e.0) {
                Blend::One(i) => map[i].1,
                Blend::Two(i, t) => mix(&map[i].1, &map[i + 1].1, t),
                Blend::None => Colour::BLACK,
            }
        }
        PigmentKind::Image(im) => {
            let p = pigment.transform.inverse_point(world);
            image_colour(im, warp_chain(&im.warps, im.turbulence.as_ref(), p))
        }
        PigmentKind::PigmentMap { pattern, map }
            if matches!(pattern.kind, PatternKind::Average) =>
        {
            average(map, at)
        }
        PigmentKind::PigmentMap { pattern, map } => {
            let p = pigment.transform.inverse_point(world);
            let v = pattern_value_at(pattern, p, at.normal);
            match blend_position(map, v, |e| e.0) {
                Blend::One(i) => pigment_at(&map[i].1, at),
                Blend::Two(i, t) => mix(
                    &pigment_at(&map[i].1, at),
                    &pigment_at(&map[i + 1].1, at),
                    t,
                ),
                Blend::None => Colour::BLACK,
            }
        }
    }
}

/// The image's colour at a pattern-space point. Checked against povray with a 4 x 2 test
/// image: column floor(u W), row floor((1 - v) H); bilinear between pixel centres
/// ((i + 0.5) / W), wrapping around.
pub fn image_colour(im: &ImageMap, p: DVec3) -> Colour {
    let (w, h) = (im.image.width, im.image.height);
    if w == 0 || h == 0 || im.image.pixels.len() < w * h || !p.is_finite() {
        return Colour::BLACK;
    }
    let (u, v) = match im.map_type {
        MapType::Planar => (p.x, p.y),
        MapType::Spherical => {
            let len = p.length();
            if len == 0.0 {
                (0.0, 0.5)
            } else {
                let u = (p.z.atan2(p.x) / TAU).rem_euclid(1.0);
                let v = (p.y / len).clamp(-1.0, 1.0).asin() / PI + 0.5;
                (u, v)
            }
        }
        MapType::Cylindrical => ((p.z.atan2(p.x) / TAU).rem_euclid(1.0), p.y),
    };
    if im.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return Colour {
            rgb: DVec3::ZERO,
            filter: 0.0,
            transmit: 1.0,
        };
    }
    let (u, v) = (u.rem_euclid(1.0), v.rem_euclid(1.0));
    let at = |i: i64, j: i64| {
        let i = i.rem_euclid(w as i64) as usize;
        let j = j.rem_euclid(h as i64) as usize;
        im.image.pixels[j * w + i]
    };
    let mut c = if im.bilinear {
        let x = u * w as f64 - 0.5;
        let y = (1.0 - v) * h as f64 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let (i, j) = (x0 as i64, y0 as i64);
        let top = mix(&at(i, j), &at(i + 1, j), fx);
        let bottom = mix(&at(i, j + 1), &at(i + 1, j + 1), fx);
        mix(&top, &bottom, fy)
    } else {
        let i = ((u * w as f64) as i64).min(w as i64 - 1);
        let j = (((1.0 - v) * h as f64) as i64).min(h as i64 - 1);
        at(i, j)
    };
    c.filter += im.filter_all;
    c.transmit += im.transmit_all;
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Transform;
    use crate::scene::{Pattern, PatternKind};

    #[test]
    fn checker_alternates_on_unit_cubes() {
        let a = Colour::rgb(1.0, 0.0, 0.0);
        let b = Colour::rgb(0.0, 1.0, 0.0);
        let mut pig = Pigment {
            kind: PigmentKind::List {
                pattern: Pattern::new(PatternKind::Checker),
                entries: vec![Pigment::solid(a), Pigment::solid(b)],
            },
            transform: Transform::IDENTITY,
            uv_mapping: false,
        };
        assert_eq!(evaluate_pigment(&pig, DVec3::new(0.5, 0.5, 0.5)), a);
        assert_eq!(evaluate_pigment(&pig, DVec3::new(1.5, 0.5, 0.5)), b);
        assert_eq!(evaluate_pigment(&pig, DVec3::new(-0.5, 0.5, 0.5)), b);
        assert_eq!(evaluate_pigment(&pig, DVec3::new(-0.5, -0.5, 0.5)), a);
        // Integer faces belong to the cube above them.
        assert_eq!(evaluate_pigment(&pig, DVec3::new(1.0, 0.0, 0.0)), b);
        pig.transform_by(&Transform::scale(DVec3::splat(2.0)).unwrap());
        assert_eq!(evaluate_pigment(&pig, DVec3::new(1.5, 0.5, 0.5)), a);
    }

    #[test]
    fn colour_map_blends_all_channels_and_steps() {
        let mut c1 = Colour::rgb(0.0, 0.0, 0.0);
        c1.transmit = 1.0;
        let c2 = Colour::rgb(1.0, 1.0, 1.0);
        let pig = Pigment {
            kind: PigmentKind::ColourMap {
                pattern: Pattern::new(PatternKind::Gradient(DVec3::X)),
                map: vec![(0.2, c1), (0.6, c2), (0.6, Colour::BLACK)],
            },
            transform: Transform::IDENTITY,
            uv_mapping: false,
        };
        let c = evaluate_pigment(&pig, DVec3::new(0.4, 0.0, 0.0));
        assert!((c.rgb.x - 0.5).abs() < 1e-9 && (c.transmit - 0.5).abs() < 1e-9);
        assert_eq!(evaluate_pigment(&pig, DVec3::new(0.1, 0.0, 0.0)), c1);
        assert_eq!(
            evaluate_pigment(&pig, DVec3::new(0.7, 0.0, 0.0)),
            Colour::BLACK
        );
    }
}
