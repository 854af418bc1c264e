//! Helices (25, 26), fitted to POV-Ray's printed values.

use std::f64::consts::{PI, TAU};

use glam::DVec3;

/// How far (u, v) is from the tube's centre under cross-section type `t`: the 2/t-norm,
/// so 1 is a circle, 2 a diamond, 3 a concave diamond and 0 a square (the limit).
pub fn cross_section(u: f64, v: f64, t: f64) -> f64 {
    let (u, v) = (u.abs(), v.abs());
    if t == 0.0 {
        return u.max(v);
    }
    let p = 2.0 / t;
    (u.powf(p) + v.powf(p)).powf(t / 2.0)
}

fn rotate(u: f64, v: f64, angle: f64) -> (f64, f64) {
    let (s, c) = angle.sin_cos();
    (u * c - v * s, u * s + v * c)
}

/// 25: P0 tubes of radius P2 winding at radius P3 about y, P1 radians per unit of height.
/// The cross-section is measured in (radial offset, height to the nearest winding / P4)
/// before rotating by P6 degrees, and never reads more than the distance through the axis
/// to the far side of the winding circle, ρ + P3 - P2.
pub fn helix1(p: DVec3, a: &[f64]) -> f64 {
    let (n, period, minor, major) = (a[0], a[1], a[2], a[3]);
    let rho = p.x.hypot(p.z);
    let turn = (n * (p.z.atan2(p.x) + p.y * period)).rem_euclid(TAU);
    let v = (turn - PI) / n / (period * a[4]);
    let (u, v) = rotate(rho - major, v, a[6].to_radians());
    (cross_section(u, v, a[5]) - minor).min(rho + major - minor)
}

/// 26: one tube of radius P2 whose centre is at angle P1·y on the circle of radius P3; the
/// cross-section lies in the horizontal plane, turned with the winding. P0, P4 and also
/// the rotation P6 have no effect (POV-Ray 3.7 prints the same values for any P6).
pub fn helix2(p: DVec3, a: &[f64]) -> f64 {
    let (period, minor, major) = (a[1], a[2], a[3]);
    let (s, c) = (p.y * period).sin_cos();
    let (u, v) = rotate(p.x - major * c, p.z - major * s, -p.y * period);
    cross_section(u, v, a[5]) - minor
}

/// 64: an Archimedean spiral in the xz plane, its arms P0 apart, of thickness P1 under
/// cross-section type P5, cut by the sphere of radius P2 (functions.inc calls P2 the outer
/// diameter, but POV-Ray takes |p| - P2). Near the axis, where the nearest arm would be
/// one of negative radius, the distance is to the first arm; and it never exceeds the
/// distance to the origin, where the spiral starts. POV-Ray reads ρ = 0 as 1e-6 (its
/// value at the origin is -P1 + 1e-6). P3 and P4 are unused.
pub fn spiral(p: DVec3, a: &[f64]) -> f64 {
    let (spacing, thickness, outer) = (a[0], a[1], a[2]);
    let mut rho = p.x.hypot(p.z);
    if rho == 0.0 {
        rho = 1e-6;
    }
    let along = rho + spacing * p.z.atan2(p.x) / TAU;
    let d = if along < 0.0 {
        spacing / 2.0 - along
    } else {
        along % spacing - spacing / 2.0
    };
    let centre = rho.hypot(p.y);
    let v = cross_section(d, p.y, a[5]).min(centre) - thickness;
    v.max(p.length() - outer)
}
