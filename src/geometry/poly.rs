//! POV-Ray's `poly`, `cubic` and `polynomial`: the surface where a polynomial in x, y, z of
//! order 2 to 7 is zero, the inside where it is negative (as `quartic`). Along a ray each
//! coordinate is linear in t, so the polynomial becomes one in t of degree at most 7, whose
//! real roots the monotone-piece walk of `roots` finds; unbounded, as in POV-Ray.

use glam::DVec3;

use super::Ray;
use super::roots::{root_bound, roots_in_wide};

/// The highest order POV-Ray accepts.
pub const MAX_ORDER: usize = 7;

/// How many coefficients a polynomial of `order` has: (n + 1)(n + 2)(n + 3) / 6.
pub const fn term_count(order: usize) -> usize {
    (order + 1) * (order + 2) * (order + 3) / 6
}

/// The exponents (x, y, z) of the terms of a polynomial of `order`, in POV-Ray's order:
/// descending powers of x, then of y, then of z (x^n, x^(n-1) y, x^(n-1) z, x^(n-1), ...),
/// the order `quartic` uses for n = 4.
pub fn term_exponents(order: usize) -> impl Iterator<Item = (u8, u8, u8)> {
    (0..=order).rev().flat_map(move |i| {
        (0..=order - i).rev().flat_map(move |j| {
            (0..=order - i - j)
                .rev()
                .map(move |k| (i as u8, j as u8, k as u8))
        })
    })
}

/// One non-zero term: c x^i y^j z^k.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Term {
    c: f64,
    e: [u8; 3],
}

/// The polynomial's non-zero terms; most scenes' polys are sparse.
#[derive(Clone, Debug, PartialEq)]
pub struct PolyData {
    order: usize,
    terms: Vec<Term>,
}

/// A ray leaving the surface starts on it only up to the root's error, which near a
/// tangency is far above the generic offset; roots this close (in the polynomial's own
/// units) are the surface the ray left, as for `quartic` (POV-Ray skips them too).
const DEPTH_TOLERANCE: f64 = 1e-4;

/// Roots beyond this distance (in the polynomial's units, from the point of the ray nearest
/// the origin) are rounding noise of far-away sheets, not surfaces a scene shows.
const REACH: f64 = 1e6;

impl PolyData {
    /// From POV-Ray's coefficient list for `order` (as many as [`term_count`]).
    pub fn new(order: usize, coefficients: &[f64]) -> PolyData {
        let order = order.min(MAX_ORDER);
        let terms = term_exponents(order)
            .zip(coefficients)
            .filter(|(_, c)| **c != 0.0)
            .map(|((i, j, k), &c)| Term { c, e: [i, j, k] })
            .collect();
        PolyData { order, terms }
    }

    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of::<PolyData>() + self.terms.capacity() * std::mem::size_of::<Term>()
    }

    pub fn value(&self, p: DVec3) -> f64 {
        let pw = powers(p, self.order);
        self.terms
            .iter()
            .map(|t| t.c * pw[t.e[0] as usize].x * pw[t.e[1] as usize].y * pw[t.e[2] as usize].z)
            .sum()
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.value(p) < 0.0
    }

    /// The gradient, which points outwards (towards positive values).
    pub fn gradient(&self, p: DVec3) -> DVec3 {
        let pw = powers(p, self.order);
        let mut g = DVec3::ZERO;
        for t in &self.terms {
            let [i, j, k] = t.e.map(usize::from);
            let (x, y, z) = (pw[i].x, pw[j].y, pw[k].z);
            if i > 0 {
                g.x += t.c * i as f64 * pw[i - 1].x * y * z;
            }
            if j > 0 {
                g.y += t.c * j as f64 * x * pw[j - 1].y * z;
            }
            if k > 0 {
                g.z += t.c * k as f64 * x * y * pw[k - 1].z;
            }
        }
        g
    }

    /// Every crossing along the whole line, in increasing order, except those at the ray's
    /// own origin (see [`DEPTH_TOLERANCE`]).
    pub fn each_hit(&self, ray: &Ray, f: impl FnMut(f64)) {
        self.each_hit_within(ray, (f64::NEG_INFINITY, f64::INFINITY), f);
    }

    /// [`PolyData::each_hit`], searched only within (lo, hi) along the ray.
    pub fn each_hit_within(&self, ray: &Ray, (lo, hi): (f64, f64), mut f: impl FnMut(f64)) {
        let d_len = ray.direction.length();
        if d_len == 0.0 || !d_len.is_finite() {
            return;
        }
        let dir = ray.direction / d_len;
        // Measured from the point of the line nearest the origin, the coefficients in s stay
        // balanced however far the ray starts.
        let s0 = -ray.origin.dot(dir);
        let o = ray.origin + dir * s0;
        let coef = self.along(o, dir);
        let coef = &coef[MAX_ORDER - self.order..];
        let reach = root_bound(coef).min(REACH * (1.0 + o.length()) + s0.abs());
        let (from, to) = ((lo * d_len - s0).max(-reach), (hi * d_len - s0).min(reach));
        if from >= to {
            return;
        }
        for &s in roots_in_wide(coef, from, to).as_slice() {
            let t = s0 + s;
            if t.abs() > DEPTH_TOLERANCE && t.is_finite() {
                f(t / d_len);
            }
        }
    }

    /// The polynomial along o + s d as coefficients of s^7 .. s^0 (highest first).
    fn along(&self, o: DVec3, d: DVec3) -> [f64; MAX_ORDER + 1] {
        let n = self.order;
        // lin[axis][m]: (o + s d)^m along that axis, as coefficients of s^0..s^m.
        let mut lin = [[[0.0f64; MAX_ORDER + 1]; MAX_ORDER + 1]; 3];
        for (axis, table) in lin.iter_mut().enumerate() {
            let (oa, da) = (o[axis], d[axis]);
            table[0][0] = 1.0;
            for m in 1..=n {
                for q in (0..=m).rev() {
                    let from_o = if q < m { table[m - 1][q] * oa } else { 0.0 };
                    let from_d = if q > 0 { table[m - 1][q - 1] * da } else { 0.0 };
                    table[m][q] = from_o + from_d;
                }
            }
        }
        let mut sum = [0.0f64; MAX_ORDER + 1];
        for t in &self.terms {
            let [i, j, k] = t.e.map(usize::from);
            let mut xy = [0.0f64; MAX_ORDER + 1];
            for (a, &xa) in lin[0][i][..=i].iter().enumerate() {
                for (b, &yb) in lin[1][j][..=j].iter().enumerate() {
                    xy[a + b] += xa * yb;
                }
            }
            for (a, &v) in xy[..=i + j].iter().enumerate() {
                for (b, &zb) in lin[2][k][..=k].iter().enumerate() {
                    sum[a + b] += t.c * v * zb;
                }
            }
        }
        sum.reverse();
        sum
    }
}

/// p's coordinates raised to 0..=order, per axis in x, y, z.
fn powers(p: DVec3, order: usize) -> [DVec3; MAX_ORDER + 1] {
    let mut out = [DVec3::ONE; MAX_ORDER + 1];
    for m in 1..=order {
        out[m] = out[m - 1] * p;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_term_order_is_povrays() {
        assert_eq!(term_count(2), 10);
        assert_eq!(term_count(4), 35);
        assert_eq!(term_count(7), 120);
        let t: Vec<_> = term_exponents(2).collect();
        assert_eq!(
            t,
            [
                (2, 0, 0),
                (1, 1, 0),
                (1, 0, 1),
                (1, 0, 0),
                (0, 2, 0),
                (0, 1, 1),
                (0, 1, 0),
                (0, 0, 2),
                (0, 0, 1),
                (0, 0, 0)
            ]
        );
        assert_eq!(term_exponents(7).count(), 120);
    }

    /// x^6 + y^6 + z^6 - 1: a rounded cube of half-size 1.
    fn sextic_cube() -> PolyData {
        let mut c = vec![0.0; term_count(6)];
        for (n, e) in term_exponents(6).enumerate() {
            c[n] = match e {
                (6, 0, 0) | (0, 6, 0) | (0, 0, 6) => 1.0,
                (0, 0, 0) => -1.0,
                _ => 0.0,
            };
        }
        PolyData::new(6, &c)
    }

    #[test]
    fn a_ray_through_a_sextic_meets_both_faces() {
        let p = sextic_cube();
        let ray = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::new(2.0, 0.0, 0.0));
        let mut hits = Vec::new();
        p.each_hit(&ray, |t| hits.push(t));
        assert_eq!(hits.len(), 2, "{hits:?}");
        assert!((hits[0] - 2.0).abs() < 1e-12 && (hits[1] - 3.0).abs() < 1e-12);
        assert!(p.inside(DVec3::ZERO) && !p.inside(DVec3::splat(1.01)));
        let g = p.gradient(DVec3::new(1.0, 0.0, 0.0));
        assert!((g - DVec3::new(6.0, 0.0, 0.0)).length() < 1e-12);
    }

    #[test]
    fn every_root_lies_within_the_bound() {
        // (s - 3)(s + 0.5)(s - 10) = s^3 - 12.5 s^2 + 25 s + 15, and a tiny leading term.
        let b = root_bound(&[1.0, -12.5, 25.0, 15.0]);
        assert!((10.0..=40.0).contains(&b), "{b}");
        assert!(root_bound(&[1e-12, 1.0, -1.0]) > 1e11);
        assert_eq!(root_bound(&[0.0, 0.0]), 0.0);
    }

    #[test]
    fn the_expansion_along_a_ray_matches_the_value() {
        // A dense order-7 polynomial with made-up coefficients.
        let c: Vec<f64> = (0..term_count(7))
            .map(|n| ((n * 37 % 11) as f64 - 5.0) * 0.1)
            .collect();
        let p = PolyData::new(7, &c);
        let (o, d) = (DVec3::new(0.3, -0.7, 1.1), DVec3::new(0.2, 0.5, -0.4));
        let coef = p.along(o, d);
        for s in [-1.3, 0.0, 0.4, 2.0] {
            let direct = p.value(o + d * s);
            let horner = coef.iter().fold(0.0, |acc, &c| acc * s + c);
            assert!((direct - horner).abs() < 1e-9 * (1.0 + direct.abs()), "{s}");
        }
    }
}
