use glam::DVec3;

use super::blend::{Blend, blend_position, mix};
use super::pattern::{pattern_index, pattern_value_at, warp_chain};
use std::f64::consts::{PI, TAU};

use crate::geometry::TexturePoint;
use crate::scene::{Colour, ImageMap, Interpolate, MapType, PatternKind, Pigment, PigmentKind};

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
    let (u, v) = image_uv(im.map_type, p);
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
    let neighbours = || {
        let x = u * w as f64 - 0.5;
        let y = (1.0 - v) * h as f64 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        ((x0 as i64, y0 as i64), (x - x0, y - y0))
    };
    let mut c = match im.interpolate {
        Interpolate::Nearest => {
            let (i, j) = nearest_pixel((u, v), (w, h));
            at(i as i64, j as i64)
        }
        Interpolate::Bilinear => {
            let ((i, j), (fx, fy)) = neighbours();
            let top = mix(&at(i, j), &at(i + 1, j), fx);
            let bottom = mix(&at(i, j + 1), &at(i + 1, j + 1), fx);
            mix(&top, &bottom, fy)
        }
        Interpolate::InverseSquare => {
            let ((i, j), (fx, fy)) = neighbours();
            inverse_square(&[
                (at(i, j), fx * fx + fy * fy),
                (at(i + 1, j), (1.0 - fx).powi(2) + fy * fy),
                (at(i, j + 1), fx * fx + (1.0 - fy).powi(2)),
                (at(i + 1, j + 1), (1.0 - fx).powi(2) + (1.0 - fy).powi(2)),
            ])
        }
    };
    c.filter += im.filter_all;
    c.transmit += im.transmit_all;
    c
}

/// Colours weighted by the inverse of their squared distance `d2` (one at distance 0
/// wins). POV-Ray's `interpolate 4`, measured on a 2 x 2 image: 0.6875 across and 0.125 off
/// a pixel centre gives that pixel 0.91 and the others 0.04, 0.04, 0.02, as 1 / d^2 does.
fn inverse_square(weighted: &[(Colour, f64); 4]) -> Colour {
    if let Some((c, _)) = weighted.iter().find(|(_, d2)| *d2 == 0.0) {
        return *c;
    }
    let total: f64 = weighted.iter().map(|(_, d2)| 1.0 / d2).sum();
    let mut sum = Colour {
        rgb: DVec3::ZERO,
        filter: 0.0,
        transmit: 0.0,
    };
    for (c, d2) in weighted {
        let k = 1.0 / d2 / total;
        sum.rgb += c.rgb * k;
        sum.filter += c.filter * k;
        sum.transmit += c.transmit * k;
    }
    sum
}

/// The texture a material_map picks at a pattern-space point from the number of the pixel
/// an image_map would show there. Measured with 3, 4 and 8 textures over the numbers 0 to
/// 11: a number below the count picks its texture, the count itself picks the last, and a
/// larger number picks itself mod the count (with 3: 0 1 2 2 1 2 0 1 2 0 1 2). Outside a
/// `once` image, the first texture.
pub fn material_index(m: &crate::scene::MaterialImage, p: DVec3) -> usize {
    let (w, h) = (m.image.width, m.image.height);
    if w == 0 || h == 0 || m.image.index.len() < w * h || !p.is_finite() || m.count == 0 {
        return 0;
    }
    let (u, v) = image_uv(m.map_type, p);
    if m.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return 0;
    }
    let (i, j) = nearest_pixel((u.rem_euclid(1.0), v.rem_euclid(1.0)), (w, h));
    let n = usize::from(m.image.index[j * w + i]);
    match n.cmp(&m.count) {
        std::cmp::Ordering::Less => n,
        std::cmp::Ordering::Equal => m.count - 1,
        std::cmp::Ordering::Greater => n % m.count,
    }
}

/// Column floor(u W) and row floor((1 - v) H) for (u, v) in [0, 1).
pub(super) fn nearest_pixel((u, v): (f64, f64), (w, h): (usize, usize)) -> (usize, usize) {
    let i = ((u * w as f64) as usize).min(w - 1);
    let j = (((1.0 - v) * h as f64) as usize).min(h - 1);
    (i, j)
}

/// An image's (u, v) at a pattern-space point, for its map type.
pub(crate) fn image_uv(map_type: MapType, p: DVec3) -> (f64, f64) {
    match map_type {
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
        // Measured with an image whose pixels hold their own column and row, read on the
        // planes y = 0 and +-0.3: u as around a cylinder; v is 0.5 on the outer equator, 0
        // (and 1) on the inner one, and grows going up the outside.
        MapType::Torus => {
            let r = p.x.hypot(p.z);
            let u = (p.z.atan2(p.x) / TAU).rem_euclid(1.0);
            (u, 0.5 + p.y.atan2(r - 1.0) / TAU)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Transform;
    use crate::scene::{Pattern, PatternKind};

    /// A 2 x 2 image (black, red over green, blue) read at u = 0.6875, v = 0.8125:
    /// POV-Ray 3.7 shows red 0.77 with `interpolate 2` and 0.91 (green 0.02, blue 0.04)
    /// with `interpolate 4`.
    #[test]
    fn interpolation_weighs_neighbours_as_povray_measured() {
        let image = crate::scene::ImageData {
            width: 2,
            height: 2,
            pixels: vec![
                Colour::BLACK,
                Colour::rgb(1.0, 0.0, 0.0),
                Colour::rgb(0.0, 1.0, 0.0),
                Colour::rgb(0.0, 0.0, 1.0),
            ],
        };
        let read = |interpolate| {
            let im = ImageMap {
                image: std::sync::Arc::new(image.clone()),
                map_type: MapType::Planar,
                interpolate,
                once: false,
                filter_all: 0.0,
                transmit_all: 0.0,
                turbulence: None,
                warps: Vec::new(),
            };
            image_colour(&im, DVec3::new(0.6875, 0.8125, 0.0)).rgb
        };
        let bilinear = read(Interpolate::Bilinear);
        assert!((bilinear.x - 0.7656).abs() < 1e-3, "{bilinear}");
        let inverse = read(Interpolate::InverseSquare);
        let measured = DVec3::new(0.91, 0.02, 0.04);
        assert!(
            (inverse - measured).abs().max_element() < 0.005,
            "{inverse}"
        );
    }

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

#[cfg(test)]
mod material_map_tests {
    use super::*;
    use crate::scene::{IndexImage, MaterialImage};

    #[test]
    fn numbers_pick_textures_as_povray_does() {
        let image = IndexImage {
            width: 12,
            height: 1,
            index: (0..12).collect(),
            palette: 0,
        };
        let m = MaterialImage {
            image: std::sync::Arc::new(image),
            map_type: MapType::Planar,
            once: false,
            count: 3,
        };
        let picks: Vec<usize> = (0..12)
            .map(|i| material_index(&m, DVec3::new((i as f64 + 0.5) / 12.0, 0.5, 0.0)))
            .collect();
        // Measured with POV-Ray 3.7 (3 textures over the numbers 0 to 11).
        assert_eq!(picks, [0, 1, 2, 2, 1, 2, 0, 1, 2, 0, 1, 2]);
        let once = MaterialImage { once: true, ..m };
        assert_eq!(material_index(&once, DVec3::new(1.5, 0.5, 0.0)), 0);
    }
}
