//! The geometric warps (`repeat`, `black_hole`, `planar`, `cylindrical`, `spherical`,
//! `toroidal`, `cubic`). Every formula here was read back from povray 3.7's printed
//! values of `function { pattern { function { x } warp { ... } } }` (and y, z) at chosen
//! points, so a pattern sees the same point in both renderers.

use std::f64::consts::{PI, TAU};

use glam::DVec3;

use super::noise::lattice_hash;
use crate::scene::{BlackHole, MappingKind, MappingWarp, Orientation, RepeatWarp};

/// `repeat`: the slab [0, w) along the axis is copied; copy k moves by k * offset, and odd
/// copies mirror along the flipped axes (within the slab along the repeat axis, through
/// 0 on the others) before the offset is added.
pub fn repeat(r: &RepeatWarp, mut p: DVec3) -> DVec3 {
    let a = r.axis;
    let k = (p[a] / r.width).floor();
    if !k.is_finite() {
        return p;
    }
    p[a] -= k * r.width;
    if k.rem_euclid(2.0) == 1.0 {
        for i in 0..3 {
            if r.flip[i] != 0.0 {
                p[i] = if i == a { r.width - p[i] } else { -p[i] };
            }
        }
    }
    p + r.offset * k
}

const BLACK_HOLE_SEED: u32 = 0x5be0_cd19;

/// `black_hole`: inside the radius the point moves away from the centre by the fraction
/// min(strength (1 - d / radius)^falloff, 1) of its distance (towards it with `inverse`).
/// With `repeat` each cell of that size has its own hole, the centre's coordinate on a
/// repeated axis at max(centre, radius) from the cell's low corner (measured for centres
/// below half the cell; povray's rule for centres beyond it is not reproduced), moved by a
/// random fraction of `turbulence` per cell (povray's jitter is its own hash's).
pub fn black_hole(b: &BlackHole, p: DVec3) -> DVec3 {
    let mut c = b.centre;
    if b.repeat != DVec3::ZERO {
        let mut cell = [0i64; 3];
        for i in 0..3 {
            let r = b.repeat[i];
            if r > 0.0 {
                let k = (p[i] / r).floor();
                cell[i] = k as i64;
                c[i] = k * r + c[i].max(b.radius);
            }
        }
        if b.jitter != DVec3::ZERO {
            let h = |s: u32| {
                let v = lattice_hash(cell[0], cell[1], cell[2], BLACK_HOLE_SEED ^ s);
                f64::from(v) / f64::from(u32::MAX) - 0.5
            };
            c += b.jitter * DVec3::new(h(1), h(2), h(3));
        }
    }
    let v = p - c;
    let d = v.length() / b.radius;
    if d >= 1.0 || d.is_nan() || d == 0.0 {
        return p;
    }
    let s = (b.strength * (1.0 - d).powf(b.falloff)).min(1.0);
    c + v * if b.inverse { 1.0 - s } else { 1.0 + s }
}

/// The angle around y from +x towards +z as a fraction of a turn, in [0, 1).
fn turn(x: f64, z: f64) -> f64 {
    let a = z.atan2(x) / TAU;
    if a < 0.0 { a + 1.0 } else { a }
}

/// The mapping warps: the point becomes (angle, height or second angle, distance), the
/// angles scaled by distance^dist_exp, then moved by the orientation matrix.
pub fn mapping(m: &MappingWarp, p: DVec3) -> DVec3 {
    let q = match m.kind {
        MappingKind::Cylindrical => {
            let r = p.x.hypot(p.z);
            DVec3::new(turn(p.x, p.z) * r.powf(m.dist_exp), p.y, r)
        }
        MappingKind::Spherical => {
            let r = p.length();
            if r == 0.0 {
                return p;
            }
            let k = r.powf(m.dist_exp);
            let polar = (-p.y / r).clamp(-1.0, 1.0).acos() / PI;
            DVec3::new(turn(p.x, p.z) * k, polar * k, r)
        }
        MappingKind::Toroidal { major_radius } => {
            if p.x == 0.0 && p.z == 0.0 {
                return p;
            }
            let rho = p.x.hypot(p.z) - major_radius;
            let minor = rho.hypot(p.y);
            let k = minor.powf(m.dist_exp);
            let around = (p.y.atan2(rho) + PI) / TAU;
            DVec3::new(turn(p.x, p.z) * k, around * k, minor)
        }
        MappingKind::Cubic => return cubic(p),
    };
    m.orient.0 * q
}

/// `planar <normal>, d`: the point's x and y with d as z, through the normal's matrix.
pub fn planar(orient: &Orientation, distance: f64, p: DVec3) -> DVec3 {
    orient.0 * DVec3::new(p.x, p.y, distance)
}

/// `cubic`: the six faces of the cube around the origin unfolded into a cross 4 wide and
/// 3 high in (x, y) = [0, 1]^2 (-x, +z, +x, -z along the middle row, +y above and -y
/// below +z); z is the largest |coordinate|.
fn cubic(p: DVec3) -> DVec3 {
    let a = p.abs();
    let m = a.max_element();
    if m == 0.0 || !m.is_finite() {
        return p;
    }
    let q = p / m;
    // (face centre u, v; local u, v) with the face width 1/4 in u and 1/3 in v.
    let (cu, cv, lu, lv) = if a.x >= a.y && a.x >= a.z {
        if p.x > 0.0 {
            (0.625, 0.5, -q.z, q.y)
        } else {
            (0.125, 0.5, q.z, q.y)
        }
    } else if a.z >= a.y {
        if p.z > 0.0 {
            (0.375, 0.5, q.x, q.y)
        } else {
            (0.875, 0.5, -q.x, q.y)
        }
    } else if p.y > 0.0 {
        (0.375, 5.0 / 6.0, q.x, -q.z)
    } else {
        (0.375, 1.0 / 6.0, q.x, q.z)
    };
    DVec3::new(cu + lu / 8.0, cv + lv / 6.0, m)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: [f64; 3]) -> bool {
        (a - DVec3::from(b)).abs().max_element() < 2e-6
    }

    #[test]
    fn mappings_match_povray_printed_values() {
        let m = |kind, dist_exp, o: DVec3| MappingWarp {
            kind,
            dist_exp,
            orient: Orientation::new(o),
        };
        let p = DVec3::new(0.3, 0.4, 0.5);
        let cyl = m(MappingKind::Cylindrical, 0.0, DVec3::Z);
        assert!(close(mapping(&cyl, p), [0.16399, 0.4, 0.583095]));
        let cyl2 = m(MappingKind::Cylindrical, 2.0, DVec3::Z);
        let q = DVec3::new(-0.7, 0.2, -0.4);
        assert!(close(mapping(&cyl2, q), [0.378706, 0.2, 0.806226]));
        let cyl110 = m(MappingKind::Cylindrical, 0.0, DVec3::new(1.0, 1.0, 0.0));
        assert!(close(mapping(&cyl110, p), [0.528269, -0.129468, 0.166885]));
        let sph = m(MappingKind::Spherical, 0.5, DVec3::Z);
        assert!(close(
            mapping(&sph, p),
            [0.137898, 0.581386, std::f64::consts::FRAC_1_SQRT_2]
        ));
        let tor = m(MappingKind::Toroidal { major_radius: 2.0 }, 1.0, DVec3::Z);
        assert!(close(mapping(&tor, p), [0.241439, 1.407811, 1.472284]));
        let cube = m(MappingKind::Cubic, 0.0, DVec3::Z);
        assert!(close(mapping(&cube, q), [0.053571, 0.547619, 0.7]));
        let r = DVec3::new(0.1, 0.9, 0.2);
        assert!(close(mapping(&cube, r), [0.388889, 0.796296, 0.9]));
        let o = Orientation::new(DVec3::new(0.3, -0.5, 0.8));
        let got = planar(&o, 0.5, DVec3::new(0.0, 1.0, 7.0));
        assert!(close(got, [0.151523, 1.363706, -0.101015]));
    }

    #[test]
    fn repeat_and_black_hole_match_povray_printed_values() {
        let r = RepeatWarp {
            axis: 0,
            width: 2.0,
            offset: DVec3::new(0.1, 0.2, 0.0),
            flip: DVec3::new(1.0, 1.0, 0.0),
        };
        assert!(close(
            repeat(&r, DVec3::new(-0.3, 0.4, 0.5)),
            [0.2, -0.6, 0.5]
        ));
        assert!(close(
            repeat(&r, DVec3::new(6.3, 0.4, 0.5)),
            [2.0, 0.2, 0.5]
        ));
        let mut b = BlackHole {
            centre: DVec3::ZERO,
            radius: 1.0,
            falloff: 2.0,
            strength: 3.0,
            inverse: false,
            repeat: DVec3::ZERO,
            jitter: DVec3::ZERO,
        };
        let x = |v: f64| DVec3::new(v, 0.0, 0.0);
        assert!(close(black_hole(&b, x(0.3)), [0.6, 0.0, 0.0]));
        assert!(close(black_hole(&b, x(0.9)), [0.927, 0.0, 0.0]));
        b.inverse = true;
        assert!(close(black_hole(&b, x(0.5)), [0.125, 0.0, 0.0]));
        b.inverse = false;
        b.strength = 1.0;
        b.centre = x(0.5);
        b.repeat = x(2.0);
        assert!(close(black_hole(&b, x(2.6)), [2.456, 0.0, 0.0]));
        assert!(close(black_hole(&b, x(-1.4)), [-1.544, 0.0, 0.0]));
    }
}
