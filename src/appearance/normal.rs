//! Normal perturbation as POV-Ray does it for patterns used as normals: the pattern is
//! sampled at the four corners of a small tetrahedron (size `accuracy`, in pattern space)
//! and the normal is tilted against the weighted sum. Measured with povray on a plane:
//! `normal { gradient x, A }` tilts the normal by -0.1333 A per unit slope whatever the
//! pattern's scale, which is 5 A times the tetrahedral sum (4/3 * 0.02 * slope).

use glam::DVec3;

use std::f64::consts::TAU;

use super::blend::{Blend, blend_position};
use super::noise::{noise, value_gradient_vector};
use super::pattern::{QUILT_SCALE, WAVE_SOURCES, pattern_value, quilt_vector, warp_point};
use crate::scene::{Normal, Pattern, PatternKind, SlopeEntry};

/// The corners of a regular tetrahedron in pattern space, oriented as POV-Ray's are: one
/// corner along +y, one in the xy plane towards +x. The orientation matters only where the
/// pattern jumps: the groove a jump leaves spans x in [-0.943, +0.471] * accuracy (measured
/// on `gradient x` with povray, two levels split at the jump). Their outer products sum to
/// 4/3 I, so smooth patterns do not see the orientation.
const TETRAHEDRON: [DVec3; 4] = [
    DVec3::new(0.942_809_041_582_063_4, -1.0 / 3.0, 0.0),
    DVec3::new(-0.471_404_520_791_031_7, -1.0 / 3.0, 0.816_496_580_927_726),
    DVec3::new(-0.471_404_520_791_031_7, -1.0 / 3.0, -0.816_496_580_927_726),
    DVec3::new(0.0, 1.0, 0.0),
];
/// POV-Ray's gain on the tetrahedral sum, times `accuracy`: the tilt does not depend on
/// the step (measured: `gradient x` tilts by 0.1333 per unit amount with `accuracy` 0.02,
/// 0.05 and 0.1), so the sum is divided by it.
const GAIN: f64 = 0.1;
/// Gain on penumbra's vector noise for bumps, fitted to povray's slope and N.L
/// distributions (tests/appearance_normals.rs): none needed.
const BUMPS_GAIN: f64 = 1.0;
/// POV-Ray's vector noise is not independent of its scalar noise: its x component is
/// `2.0408 Noise - 1.0521` of the same point (bumps' x tilt against the bumps pattern,
/// 512 x 512 points, correlation 0.99993, residual 0.003, the quantisation of the probe).
/// Dents scales that vector by `Noise^3`, so its x tilt is a quartic in the dents value:
/// a floor of -0.0153 near Noise = 0.39 and a long positive tail (measured the same way:
/// `n^3 (2.0422 n - 1.0530)`, residual 3e-4). y and z are independent noises.
const NOISE_TO_X: (f64, f64) = (2.0408, -1.0521);
/// With that rule on penumbra's own noise the dents tilt's power, as N.L and as slope, is
/// 0.87-0.96 and 0.86-0.91 of povray's in every band over 64 slices; a gain of 1.03 brings
/// them to 0.97-1.07 and 0.91-0.97 (the tilt, about Noise^4, lives on the highest peaks,
/// and N.L's power grows as the gain's fourth power). Fitted on 16 slices, where one set of
/// peaks decides, an earlier rule had a gain of 1.07 and an octave at 8x frequency on the
/// peaks; over 64 slices it put 1.3-1.7x povray's power in the finest bands.
const DENTS_GAIN: f64 = 1.03;
/// Wrinkles sums the absolute vector noise over ten octaves, weights halving: every
/// component of povray's wrinkles perturbation is positive (mean +0.42 per unit amount in
/// x, y and z), which the absolute values reproduce.
const WRINKLES_OCTAVES: usize = 10;

/// The unit normal `n` (world space) tilted by `normal` at world point `p`.
pub fn perturb(normal: &Normal, p: DVec3, n: DVec3) -> DVec3 {
    if !normal.normal_map.is_empty() {
        return blend_normals(normal, p, n);
    }
    if normal.amount == 0.0 {
        return n;
    }
    let q = normal.transform.inverse_point(p);
    if let crate::scene::PatternKind::BumpMap(b) = &normal.pattern.kind {
        return bump_map_normal(normal, b, q, n);
    }
    // Patterns with their own perturbation ignore a slope map (measured: `ripples 1
    // slope_map {[0 <0,5>][1 <1,5>]}` tilts exactly as plain `ripples 1`).
    let tilt = normal.amount
        * match own_normal(&normal.pattern, q) {
            Some(v) => v,
            None => {
                let mut sum = DVec3::ZERO;
                for v in TETRAHEDRON {
                    let value = pattern_value(&normal.pattern, q + v * normal.accuracy);
                    sum += slope_height(&normal.slope_map, value) * v;
                }
                -GAIN / normal.accuracy * sum
            }
        };
    if tilt == DVec3::ZERO || !tilt.is_finite() {
        return n;
    }
    in_pattern_space(normal, n, tilt)
}

/// The unit normal `n` tilted by `tilt` in pattern space: POV-Ray takes the normal there
/// (by the transpose of the pattern's transform), adds the tilt and brings the sum back as
/// a normal. A uniform scale changes nothing; measured on `gradient x 0.5` (tilt 0.0667 on
/// a plane seen along z), `scale <0.1, 1, 1>` and `scale <1, 1, 10>` make it 0.667 and
/// `scale <1, 1, 0.1>` 0.0067.
fn in_pattern_space(normal: &Normal, n: DVec3, tilt: DVec3) -> DVec3 {
    let m = normal.transform.inverse_normal(n).normalize_or(n);
    normal.transform.normal(m + tilt).normalize_or(n)
}

/// `bump_map`, measured with POV-Ray 3.7 on a plane seen from either side through three
/// lights (normals recovered to 1e-3) with single bright pixels and ramps: the pixel under
/// the point (as an image_map picks it, heights from the stored values, not decoded) and
/// the two diagonal neighbours in the row below give d1 = h(i+1, j+1) - h, d2 = h(i-1,
/// j+1) - h; the normal becomes N + s (d1 - d2) / 2 u + s (d1 + d2) / 2 v renormalised, with
/// s the bump_size, u = Y x N and v = N x u for the pattern's y axis Y (the x tilt follows
/// the side seen, the y tilt does not). All this happens in pattern space: the normal goes
/// there and back as normals do, so a scale that stretches z more than x and y flattens the
/// bumps (measured on a plane seen along z: `scale <2, 2, 1>` halves the tilt, `scale 2`
/// leaves it). Outside a `once` image the normal is unchanged.
fn bump_map_normal(normal: &Normal, b: &crate::scene::BumpMap, q: DVec3, n: DVec3) -> DVec3 {
    let im = &b.image;
    let (w, h) = (im.width as i64, im.height as i64);
    if w == 0 || h == 0 || !q.is_finite() {
        return n;
    }
    let (u, v) = super::pigment::image_uv(b.map_type, q);
    if b.once && !((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v)) {
        return n;
    }
    let (u, v) = (u.rem_euclid(1.0), v.rem_euclid(1.0));
    let height = |x: f64, y: f64| -> f64 {
        let at = |i: i64, j: i64| {
            f64::from(im.heights[(j.rem_euclid(h) * w + i.rem_euclid(w)) as usize])
        };
        let (x0, y0) = (x.floor(), y.floor());
        let (i, j) = (x0 as i64, y0 as i64);
        if !b.bilinear {
            return at(i, j);
        }
        let (fx, fy) = (x - x0, y - y0);
        let top = at(i, j) * (1.0 - fx) + at(i + 1, j) * fx;
        let bottom = at(i, j + 1) * (1.0 - fx) + at(i + 1, j + 1) * fx;
        top * (1.0 - fy) + bottom * fy
    };
    // Pixel coordinates: the nearest pixel's, or (bilinear) measured from pixel centres.
    let (x, y) = if b.bilinear {
        (u * w as f64 - 0.5, (1.0 - v) * h as f64 - 0.5)
    } else {
        let (i, j) = super::pigment::nearest_pixel((u, v), (im.width, im.height));
        (i as f64, j as f64)
    };
    let h0 = height(x, y);
    let (d1, d2) = (height(x + 1.0, y + 1.0) - h0, height(x - 1.0, y + 1.0) - h0);
    let s = normal.amount;
    let m = normal.transform.inverse_normal(n).normalize_or_zero();
    let across = DVec3::Y.cross(m).normalize_or_zero();
    let up = m.cross(across);
    in_pattern_space(
        normal,
        n,
        across * (s * (d1 - d2) / 2.0) + up * (s * (d1 + d2) / 2.0),
    )
}

/// `normal_map`: the two entries around the pattern value each perturb the normal, and
/// the unit results are mixed linearly and renormalised. Measured on a plane with entries
/// tilting by 1.333 and 0.333 in different directions: mixing the unit normals fits to
/// 6e-4 everywhere, mixing the tilts is off by 0.1. The outer normal's amount (or
/// `bump_size`) has no effect (measured with 0.2 and 3).
fn blend_normals(normal: &Normal, p: DVec3, n: DVec3) -> DVec3 {
    let map = &normal.normal_map;
    if matches!(normal.pattern.kind, crate::scene::PatternKind::Average) {
        return average_normals(map, p, n);
    }
    let value = pattern_value(&normal.pattern, normal.transform.inverse_point(p));
    match blend_position(map, value, |e| e.0) {
        Blend::None => n,
        Blend::One(i) => perturb(&map[i].1, p, n),
        Blend::Two(i, w) => {
            let a = perturb(&map[i].1, p, n);
            let b = perturb(&map[i + 1].1, p, n);
            (a * (1.0 - w) + b * w).normalize_or(n)
        }
    }
}

/// `average normal_map`: the entries' unit normals weighted by their values, renormalised.
fn average_normals(map: &[(f64, Normal)], p: DVec3, n: DVec3) -> DVec3 {
    let mut sum = DVec3::ZERO;
    for (w, entry) in map {
        sum += perturb(entry, p, n) * *w;
    }
    sum.normalize_or(n)
}

/// The height a slope map gives a pattern value: between neighbouring entries a cubic
/// Hermite curve through both heights with both slopes, in the interval's own parameter t
/// (0 to 1); below the first entry its height, above the last the last. Measured on
/// `gradient x` with six maps (unequal spacing, a step, values outside the map): the tilt
/// is the tetrahedral difference of this height to the half-float precision (6e-4).
fn slope_height(map: &[SlopeEntry], value: f64) -> f64 {
    if map.is_empty() {
        return value;
    }
    match blend_position(map, value, |e| e.value) {
        Blend::None => value,
        Blend::One(i) => map[i].height,
        Blend::Two(i, t) => {
            let (a, b) = (map[i], map[i + 1]);
            let (t2, t3) = (t * t, t * t * t);
            (2.0 * t3 - 3.0 * t2 + 1.0) * a.height
                + (t3 - 2.0 * t2 + t) * a.slope
                + (3.0 * t2 - 2.0 * t3) * b.height
                + (t3 - t2) * b.slope
        }
    }
}

/// The perturbation (per unit amount, pattern space) of the patterns POV-Ray gives their
/// own normal instead of the tetrahedral difference. It is added to the normal that faces
/// the ray (measured: a plane seen from either side tilts the same way in world space).
fn own_normal(pattern: &Pattern, q: DVec3) -> Option<DVec3> {
    let waves = |weighted: bool| {
        // Each source pushes the normal along the direction away from it by the sine of
        // its wave: measured on povray's probe planes to 2e-4 (amount 0.05) and 4e-4 in
        // the normal at amount 1; `frequency` and `phase` act inside the sine only, and
        // waves' amplitude falls as 1 / (source frequency), not with `frequency`.
        let p = warp_point(pattern, q);
        let mut sum = DVec3::ZERO;
        for (s, f) in WAVE_SOURCES {
            let f = if weighted { f } else { 1.0 };
            let d = p - DVec3::from(s);
            let r = d.length();
            if r > 0.0 {
                let phase = TAU * (r * f * pattern.frequency + pattern.phase);
                sum += d / r * phase.sin() / f;
            }
        }
        sum / WAVE_SOURCES.len() as f64
    };
    Some(match pattern.kind {
        PatternKind::Ripples => waves(false),
        PatternKind::Waves => waves(true),
        PatternKind::Bumps => BUMPS_GAIN * value_gradient_vector(warp_point(pattern, q)),
        PatternKind::Dents => {
            let p = warp_point(pattern, q);
            let n = noise(p);
            let v = value_gradient_vector(p);
            DENTS_GAIN * n * n * n * DVec3::new(NOISE_TO_X.0 * n + NOISE_TO_X.1, v.y, v.z)
        }
        PatternKind::Wrinkles => {
            let p = warp_point(pattern, q);
            let mut sum = value_gradient_vector(p).abs();
            let mut f = 2.0;
            for _ in 1..WRINKLES_OCTAVES {
                sum += value_gradient_vector(p * f).abs() / f;
                f *= 2.0;
            }
            sum
        }
        // The bulge vector itself (measured on a plane over one cube with three lights:
        // residual 1e-5, the 16-bit precision, against 0.006 for the finite difference).
        PatternKind::Quilted(qu) => QUILT_SCALE * quilt_vector(&qu, warp_point(pattern, q)),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Transform;

    #[test]
    fn gradient_normal_matches_povray_probe() {
        // povray: plane facing -z, light along the view: N.L = 0.9978 for amount 0.5,
        // 0.9912 for amount 1, independent of `scale 2`.
        let mut nor = Normal::new(Pattern::new(PatternKind::Gradient(DVec3::X)));
        let n = -DVec3::Z;
        for (amount, expect) in [(0.5, 0.9978), (1.0, 0.9912)] {
            nor.amount = amount;
            let p = DVec3::new(0.3, 0.1, 0.0);
            let m = perturb(&nor, p, n);
            assert!((m.dot(n) - expect).abs() < 2e-4, "{}", m.dot(n));
            // Tilted towards -x.
            assert!(m.x < 0.0);
        }
        nor.transform_by(&Transform::scale(DVec3::splat(2.0)).unwrap());
        let m = perturb(&nor, DVec3::new(0.6, 0.1, 0.0), n);
        assert!((m.dot(n) - 0.9912).abs() < 2e-4);
    }

    #[test]
    fn ripples_normal_matches_povray_probe() {
        // povray: `normal { ripples 1 }` on the plane z = 0.5 seen from -z, at
        // (-3.125, 2.2917): the normal facing the camera read (0.0315, -0.0990, -0.9946).
        let nor = Normal {
            amount: 1.0,
            ..Normal::new(Pattern::new(PatternKind::Ripples))
        };
        let m = perturb(&nor, DVec3::new(-3.125, 2.291_666_7, 0.5), -DVec3::Z);
        let want = DVec3::new(0.0315, -0.0990, -0.9946);
        assert!((m - want).abs().max_element() < 1e-3, "{m}");
    }

    fn slope(value: f64, height: f64, slope: f64) -> SlopeEntry {
        SlopeEntry {
            value,
            height,
            slope,
        }
    }

    /// The x tilt of a plane facing -z (the normal's x over its -z), as the probes read it.
    fn x_tilt(nor: &Normal, x: f64) -> f64 {
        let m = perturb(nor, DVec3::new(x, -0.31, 0.0), -DVec3::Z);
        m.x / -m.z
    }

    #[test]
    fn slope_map_matches_povray_probe() {
        // povray, `gradient x, 1 slope_map {...}` on a plane facing -z, light along the view
        // and two at 45 degrees: x tilts read at these x.
        let mut nor = Normal {
            amount: 1.0,
            ..Normal::new(Pattern::new(PatternKind::Gradient(DVec3::X)))
        };
        nor.slope_map = vec![slope(0.0, 0.0, 0.0), slope(1.0, 1.0, 0.0)];
        for (x, want) in [
            (0.22625, -0.14227),
            (0.52625, -0.19962),
            (0.92625, -0.05120),
        ] {
            let t = x_tilt(&nor, x);
            assert!((t - want).abs() < 1e-3, "{x}: {t}");
        }
        // Slopes are per unit of the interval's parameter, not per unit value.
        nor.slope_map = vec![
            slope(0.0, 0.0, 1.0),
            slope(0.5, 1.0, 1.0),
            slope(1.0, 0.0, -1.0),
        ];
        for (x, want) in [(0.15125, -0.26681), (0.65125, 0.24294), (0.85125, 0.44063)] {
            let t = x_tilt(&nor, x);
            assert!((t - want).abs() < 1e-3, "{x}: {t}");
        }
    }

    #[test]
    fn accuracy_does_not_change_the_tilt() {
        // povray: `gradient x, 2 accuracy 0.1` tilts by -0.2668.
        let nor = Normal {
            amount: 2.0,
            accuracy: 0.1,
            ..Normal::new(Pattern::new(PatternKind::Gradient(DVec3::X)))
        };
        assert!((x_tilt(&nor, 0.5) + 0.2668).abs() < 2e-4);
    }

    #[test]
    fn ripples_ignore_a_slope_map() {
        let plain = Normal {
            amount: 1.0,
            ..Normal::new(Pattern::new(PatternKind::Ripples))
        };
        let mapped = Normal {
            slope_map: vec![slope(0.0, 0.0, 5.0), slope(1.0, 1.0, 5.0)],
            ..plain.clone()
        };
        let p = DVec3::new(0.4, -0.35, 0.0);
        assert_eq!(
            perturb(&plain, p, -DVec3::Z),
            perturb(&mapped, p, -DVec3::Z)
        );
    }

    #[test]
    fn normal_map_mixes_unit_normals_as_povray() {
        // povray: `gradient x, 0.2 normal_map { [0 gradient y, -10][1 gradient x, -2.5] }`
        // at x = 0.41625 gave the normal (0.1482, 0.5253, -0.8379), the same with any
        // outer amount.
        let entry = |dir: DVec3, amount: f64| Normal {
            amount,
            ..Normal::new(Pattern::new(PatternKind::Gradient(dir)))
        };
        let nor = Normal {
            amount: 0.2,
            normal_map: vec![(0.0, entry(DVec3::Y, -10.0)), (1.0, entry(DVec3::X, -2.5))],
            ..Normal::new(Pattern::new(PatternKind::Gradient(DVec3::X)))
        };
        let m = perturb(&nor, DVec3::new(0.41625, -0.31125, 0.0), -DVec3::Z);
        let want = DVec3::new(0.1482, 0.5253, -0.8379);
        assert!((m - want).abs().max_element() < 1e-3, "{m}");
    }
}

#[cfg(test)]
mod bump_map_tests {
    use super::*;
    use crate::scene::{BumpMap, HeightImage, Pattern, PatternKind};

    /// POV-Ray's normals around one white pixel (row 3, column 3) of a black 8 x 8 image on
    /// the plane z = 0 seen from -z, recovered from three renders: (row, column, normal).
    const MEASURED: [(usize, usize, [f64; 3]); 4] = [
        (2, 2, [-0.409, 0.408, -0.816]),
        (2, 4, [0.408, 0.408, -0.816]),
        (3, 3, [0.0, -0.707, -0.707]),
        (2, 3, [0.0, 0.0, -1.0]),
    ];

    #[test]
    fn one_bright_pixel_tilts_as_povray_measured() {
        let mut heights = vec![0.0; 64];
        heights[3 * 8 + 3] = 1.0;
        let image = HeightImage {
            width: 8,
            height: 8,
            heights,
        };
        let kind = PatternKind::BumpMap(BumpMap {
            image: std::sync::Arc::new(image),
            map_type: crate::scene::MapType::Planar,
            once: false,
            bilinear: false,
        });
        let mut normal = Normal::new(Pattern::new(kind));
        normal.amount = 1.0;
        for (row, col, expected) in MEASURED {
            let p = DVec3::new(
                (col as f64 + 0.5) / 8.0,
                1.0 - (row as f64 + 0.5) / 8.0,
                0.0,
            );
            let n = perturb(&normal, p, -DVec3::Z);
            let e = DVec3::from_array(expected);
            assert!((n - e).length() < 2e-3, "({row}, {col}): {n} against {e}");
        }
    }

    /// `normal { gradient x 0.5 }` on the plane z = 0 seen from -z: POV-Ray's tilt (x over
    /// z of the normal, recovered through three lights) is 0.0667 under `scale 1` and `scale
    /// 2`, 0.667 under `scale <0.1, 1, 1>` and `<1, 1, 10>`, 0.0067 under `<1, 1, 0.1>`.
    #[test]
    fn scales_that_are_not_uniform_tilt_as_povray_measured() {
        let measured = [
            (DVec3::ONE, 0.0667),
            (DVec3::splat(2.0), 0.0667),
            (DVec3::new(0.1, 1.0, 1.0), 0.6667),
            (DVec3::new(1.0, 1.0, 10.0), 0.6667),
            (DVec3::new(1.0, 1.0, 0.1), 0.0067),
        ];
        for (scale, expected) in measured {
            let mut normal = Normal::new(Pattern::new(PatternKind::Gradient(DVec3::X)));
            normal.amount = 0.5;
            normal.transform = crate::geometry::Transform::scale(scale).expect("non-zero");
            let n = perturb(&normal, DVec3::new(0.05, 0.5, 0.0) * scale, -DVec3::Z);
            let tilt = n.x.abs() / n.z.abs();
            assert!(
                (tilt - expected).abs() < 0.002 * expected.max(0.1),
                "{scale}: {tilt}"
            );
        }
    }

    /// One step of height between two pixels, on the plane z = 0 seen from -z, under a
    /// pattern transform: POV-Ray perturbs the normal in pattern space (measured: `scale
    /// <2, 2, 1>` halves the tilt that `scale 2` gives, `scale <2, 2, 4>` doubles it).
    #[test]
    fn the_normal_is_perturbed_in_pattern_space() {
        let image = HeightImage {
            width: 2,
            height: 1,
            heights: vec![0.0, 1.0],
        };
        let kind = PatternKind::BumpMap(BumpMap {
            image: std::sync::Arc::new(image),
            map_type: crate::scene::MapType::Planar,
            once: false,
            bilinear: false,
        });
        let tilt = |scale: DVec3| {
            let mut normal = Normal::new(Pattern::new(kind.clone()));
            normal.amount = 0.5;
            normal.transform = crate::geometry::Transform::scale(scale).expect("non-zero");
            let n = perturb(&normal, scale * DVec3::new(0.25, 0.5, 0.0), -DVec3::Z);
            n.truncate().length() / n.z.abs()
        };
        let uniform = tilt(DVec3::splat(2.0));
        assert!((uniform - tilt(DVec3::ONE)).abs() < 1e-12);
        assert!((tilt(DVec3::new(2.0, 2.0, 1.0)) - uniform / 2.0).abs() < 1e-12);
        assert!((tilt(DVec3::new(2.0, 2.0, 4.0)) - uniform * 2.0).abs() < 1e-12);
    }
}
