//! POV-Ray's superellipsoid: g(x, y, z) = (|x|^p + |y|^p)^(p_z / p) + |z|^p_z = 1 inside the
//! unit cube, with p = 2 / e (east-west) and p_z = 2 / n (north-south).
//!
//! Along a ray, f(t) = g - 1 is convex when both exponents are at least 1 (a norm raised to
//! a power >= 1, plus a convex term), so it has at most two roots, which Newton's steps on
//! the norm g^(1/p_z) from either end of the ray's span in the unit cube reach without
//! passing them. Otherwise (e or n above 2, the pinched stars) the span is narrowed to a
//! convex shape around the star, cut where it crosses the coordinate planes, each piece is
//! halved where bounds on g do not rule out a crossing, and sign changes and dips in the
//! smallest parts are refined. Grazing rays near a tangency find the minimum itself, so
//! they neither miss the surface nor see holes.

use glam::DVec3;

use super::{Aabb, Ray};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Superellipsoid {
    /// 2 / e, the exponent of x and y.
    p: f64,
    /// 2 / n, the exponent of z.
    p_z: f64,
    /// 1 / p and 1 / p_z, kept: a division is a fifth of a power's time, and each value
    /// would take one or two.
    inverse: (f64, f64),
    /// p_z / p.
    ratio: f64,
    /// Whether neither p_z nor p_z / p is one of [`power`]'s exact exponents, so that
    /// the radial power is best found as one `exp2` of a sum of logarithms.
    logarithmic: bool,
}

/// How close to its origin (in the unit cube's units) a ray ignores the surface: the ray
/// leaving the surface starts on it only up to the root's error.
const DEPTH_TOLERANCE: f64 = 1e-7;

/// Halvings of a piece of the ray for the non-convex shapes: where bounds do not rule
/// out a crossing, intervals of 1/32 of the piece are searched, finer than the 24 samples
/// a piece took before (superel3: 13% fewer instructions with 1/64, 17% with 1/32, 21%
/// with 1/16; all three byte-identical images at 80x60).
const DEPTH: u32 = 5;

/// A part of the ray's piece, g - 1 at its ends and how many halvings made it.
#[derive(Clone, Copy, Debug, Default)]
struct Interval {
    t: (f64, f64),
    f: (f64, f64),
    depth: u32,
}

impl Superellipsoid {
    /// From POV-Ray's `<e, n>`; exponents are clamped away from zero as a box is the limit.
    pub fn new(east_west: f64, north_south: f64) -> Superellipsoid {
        let e = east_west.abs().max(1e-4);
        let n = north_south.abs().max(1e-4);
        Superellipsoid::with_exponents(2.0 / e, 2.0 / n)
    }

    fn with_exponents(p: f64, p_z: f64) -> Superellipsoid {
        Superellipsoid {
            p,
            p_z,
            inverse: (1.0 / p, 1.0 / p_z),
            ratio: p_z / p,
            logarithmic: !exact_power(p_z) && !exact_power(p_z / p),
        }
    }

    pub fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
    }

    /// g - 1: negative inside.
    #[inline]
    pub fn value(&self, q: DVec3) -> f64 {
        let (rp, _) = self.radial_power(q);
        rp + power(q.z.abs(), self.p_z) - 1.0
    }

    /// The gradient of g (outward on the surface).
    pub fn gradient(&self, q: DVec3) -> DVec3 {
        self.value_and_gradient(q).1
    }

    /// The larger m of |x| and |y| and w = (s / m)^p of the smaller s: |x|^p + |y|^p is
    /// m^p (1 + w). So computed, with exponents in the hundreds, neither underflows to 0
    /// inside the shape (or overflows outside it), which made holes and false crossings.
    #[inline]
    fn planar(&self, q: DVec3) -> (f64, f64) {
        let (ax, ay) = (q.x.abs(), q.y.abs());
        let (m, s) = (ax.max(ay), ax.min(ay));
        if m == 0.0 {
            return (0.0, 0.0);
        }
        (m, power(s / m, self.p))
    }

    /// (|x|^p + |y|^p)^(p_z / p) = m^p_z (1 + w)^(p_z / p) ([`Superellipsoid::planar`]),
    /// and w: one `exp2` of p_z log2 m + (p_z / p) log2 (1 + w), which neither overflows
    /// nor underflows on the way. Where an exponent is exact, two powers after w, side by
    /// side (m's power does not wait for w's; three powers one after another took a
    /// quarter more time); past p_z / p = 64 the second could overflow where the first
    /// underflows, so r = m (1 + w)^(1/p) comes first.
    #[inline]
    fn radial_power(&self, q: DVec3) -> (f64, f64) {
        let (m, w) = self.planar(q);
        let rp = if self.logarithmic {
            (self.p_z * m.log2() + self.ratio * (1.0 + w).log2()).exp2()
        } else if self.ratio <= 64.0 {
            power(m, self.p_z) * power(1.0 + w, self.ratio)
        } else {
            power(m * power(1.0 + w, self.inverse.0), self.p_z)
        };
        (rp, w)
    }

    /// g - 1 and its gradient from the same four powers: d g / dx = p_z r^p_z share_x / |x|
    /// (a shared power, where computing the gradient apart took six more `powf`; a ray's
    /// time on these shapes is nearly all `powf`).
    #[inline]
    fn value_and_gradient(&self, q: DVec3) -> (f64, DVec3) {
        let (g, gradient) = self.sum_and_gradient(q);
        (g - 1.0, gradient)
    }

    /// g and its gradient ([`Superellipsoid::value_and_gradient`]).
    #[inline]
    fn sum_and_gradient(&self, q: DVec3) -> (f64, DVec3) {
        let pz = self.p_z;
        let (rp, w) = self.radial_power(q);
        let [share_x, share_y] = shares(q.x.abs(), q.y.abs(), w);
        let az = q.z.abs();
        let zp = power(az, pz);
        let gradient = DVec3::new(
            pz * rp * per_unit(share_x, q.x),
            pz * rp * per_unit(share_y, q.y),
            pz * per_unit(zp, q.z),
        );
        (rp + zp, gradient)
    }

    /// N = g^(1 / p_z), 1 on the surface, and its gradient. With both exponents at least 1
    /// N is a norm (a p_z-norm of a p-norm), so along a line it is convex and grows only
    /// linearly, where g grows as its p_z-th power: with exponents in the hundreds Newton's
    /// steps on g crept toward the surface by a factor e a step. Where g overflows (p_z / p
    /// in the thousands), N is computed from the larger and smaller of r and |z|.
    #[inline]
    fn norm_and_gradient(&self, q: DVec3) -> (f64, DVec3) {
        let (g, gradient) = self.sum_and_gradient(q);
        if !(g.is_finite() && gradient.is_finite()) {
            return self.scaled_norm_and_gradient(q);
        }
        if g == 0.0 {
            return (0.0, DVec3::ZERO);
        }
        let n = power(g, self.inverse.1);
        (n, gradient * (n * self.inverse.1 / g))
    }

    /// [`Superellipsoid::norm_and_gradient`] without an overflow: r = m (1 + w)^(1/p), and
    /// N from the larger and smaller of r and |z| the way r is from |x| and |y|.
    fn scaled_norm_and_gradient(&self, q: DVec3) -> (f64, DVec3) {
        let (m, w) = self.planar(q);
        let r = m * power(1.0 + w, self.inverse.0);
        let [share_x, share_y] = shares(q.x.abs(), q.y.abs(), w);
        let az = q.z.abs();
        let (m, s) = (r.max(az), r.min(az));
        if m == 0.0 {
            return (0.0, DVec3::ZERO);
        }
        let v = power(s / m, self.p_z);
        let n = m * power(1.0 + v, self.inverse.1);
        let [share_r, share_z] = shares(r, az, v);
        // dN/dx = (r / N)^(p_z - 1) (|x| / r)^(p - 1) sgn x = share_r share_x N / x.
        let gradient = DVec3::new(
            share_r * n * per_unit(share_x, q.x),
            share_r * n * per_unit(share_y, q.y),
            n * per_unit(share_z, q.z),
        );
        (n, gradient)
    }

    /// N - 1 ([`Superellipsoid::norm_and_gradient`]) and its derivative along the ray at t.
    #[inline]
    fn norm_on_line(&self, ray: &Ray, t: f64) -> (f64, f64) {
        let (n, g) = self.norm_and_gradient(ray.at(t));
        (n - 1.0, g.dot(ray.direction))
    }

    pub fn inside(&self, q: DVec3) -> bool {
        self.value(q) < -1e-12
    }

    /// A convex superellipsoid around this one: its exponents raised to at least 1. A
    /// p-norm grows as p falls, and a power below 1 of a value below 1 is the larger, so
    /// g only falls with the raise.
    fn hull(&self) -> Superellipsoid {
        Superellipsoid::with_exponents(self.p.max(1.0), self.p_z.max(1.0))
    }

    fn convex(&self) -> bool {
        self.p >= 1.0 && self.p_z >= 1.0
    }

    /// Calls `f` with every crossing along the line, in increasing order, until it returns
    /// false.
    pub fn each_hit(&self, ray: &Ray, mut f: impl FnMut(f64) -> bool) {
        // The line within the cube, slightly enlarged so the faces of a box-like shape are
        // not cut by the clip.
        let inv = ray.direction.recip();
        let lo = (DVec3::splat(-1.0 - 1e-9) - ray.origin) * inv;
        let hi = (DVec3::splat(1.0 + 1e-9) - ray.origin) * inv;
        let t0 = lo.min(hi).max_element();
        let t1 = lo.max(hi).min_element();
        if t0 >= t1 || t0.is_nan() || !t0.is_finite() || !t1.is_finite() {
            return;
        }
        let tolerance = DEPTH_TOLERANCE / ray.direction.length().max(1e-300);
        let mut keep = |t: f64| t.abs() <= tolerance || f(t);
        if self.convex() {
            self.convex_hits(ray, t0, t1, &mut keep);
            return;
        }
        // Search only where the line is inside the convex hull.
        let Some((lo, hi)) = self.hull().convex_span(ray, t0, t1) else {
            return;
        };
        let pad = 1e-9 * (t1 - t0);
        let (t0, t1) = ((lo - pad).max(t0), (hi + pad).min(t1));
        // Cut at the coordinate planes, where |.| makes the function kink.
        let mut cuts = [t0, t1, t1, t1, t1];
        let mut n = 1;
        for axis in 0..3 {
            let t = -ray.origin[axis] * inv[axis];
            if t > t0 && t < t1 {
                cuts[n] = t;
                n += 1;
            }
        }
        cuts[n] = t1;
        cuts[..=n].sort_by(f64::total_cmp);
        for w in cuts[..=n].windows(2) {
            if !self.bounded_hits(ray, w[0], w[1], &mut keep) {
                return;
            }
        }
    }

    #[inline]
    fn along(&self, ray: &Ray, t: f64) -> f64 {
        self.value(ray.at(t))
    }

    /// f and its derivative along the ray at t.
    #[inline]
    fn on_line(&self, ray: &Ray, t: f64) -> (f64, f64) {
        let (v, g) = self.value_and_gradient(ray.at(t));
        (v, g.dot(ray.direction))
    }

    #[inline]
    fn slope(&self, ray: &Ray, t: f64) -> f64 {
        self.on_line(ray, t).1
    }

    /// At most two roots in [a, b] of a convex shape's N - 1 (zero where f is): the entry,
    /// found by Newton's steps from a where N(a) > 1, and the exit, from b where N(b) > 1
    /// (only if `f` asks for more). Each step costs one norm and gradient (four or five
    /// `powf`), where searching f's minimum first and then bracketing each root took two to
    /// three times as many. Where the steps miss a sign change that is there (rounding),
    /// regula falsi brackets it.
    fn convex_hits(&self, ray: &Ray, a: f64, b: f64, f: &mut impl FnMut(f64) -> bool) {
        let ((fa, sa), (fb, sb)) = (self.norm_on_line(ray, a), self.norm_on_line(ray, b));
        let tol = root_tolerance(a, b);
        let mut entry = a;
        if fa > 0.0 {
            entry = match self.newton(ray, (a, fa, sa), b, tol) {
                Some(t) => t,
                // Both ends outside and the slope turns before zero: the line misses.
                None if fb > 0.0 => return,
                None => self.root(ray, a, b, self.along(ray, a)),
            };
            if !f(entry) {
                return;
            }
        }
        if fb > 0.0 {
            let exit = match self.newton(ray, (b, fb, sb), entry, tol) {
                Some(t) => t,
                None if fa > 0.0 => entry,
                None => self.root(ray, a, b, self.along(ray, a)),
            };
            let _ = f(exit);
        }
    }

    /// Where the line is inside the convex shape within [a, b], if anywhere; where
    /// Newton's steps miss a sign change by rounding, the span reaches to the end (it
    /// bounds a search).
    fn convex_span(&self, ray: &Ray, a: f64, b: f64) -> Option<(f64, f64)> {
        let ((fa, sa), (fb, sb)) = (self.norm_on_line(ray, a), self.norm_on_line(ray, b));
        let tol = root_tolerance(a, b);
        let lo = if fa <= 0.0 {
            a
        } else {
            match self.newton(ray, (a, fa, sa), b, tol) {
                Some(t) => t,
                None if fb > 0.0 => return None,
                None => a,
            }
        };
        let hi = if fb <= 0.0 {
            b
        } else {
            self.newton(ray, (b, fb, sb), lo, tol).unwrap_or(b)
        };
        Some((lo, hi))
    }

    /// Newton's steps on the convex N - 1 from `start` = (t, N(t) - 1 > 0, its slope)
    /// toward `limit`: a convex function lies above its tangents, so from outside its steps
    /// never pass the nearest root on that side and rise to it. None where the slope stops
    /// leading down toward `limit` (N's least value is above 1), a step passes `limit`, or
    /// a value is not finite. At a tangency the steps only halve the distance to the
    /// touching point: 80 of them come within 2^-80 of it.
    fn newton(&self, ray: &Ray, start: (f64, f64, f64), limit: f64, tol: f64) -> Option<f64> {
        let (mut t, mut v, mut s) = start;
        let toward = (limit - t).signum();
        for _ in 0..80 {
            if !(v.is_finite() && s.is_finite()) || s * toward >= 0.0 {
                return None;
            }
            let next = t - v / s;
            if (next - limit) * toward > 0.0 {
                return None;
            }
            if (next - t).abs() <= tol {
                return Some(next);
            }
            t = next;
            (v, s) = self.norm_on_line(ray, t);
            if v <= 0.0 {
                return Some(t);
            }
        }
        Some(t)
    }

    /// Roots in [a, b] (a piece of the line where no coordinate changes sign), nearest
    /// first, by halving: g rises with each of |x|, |y| and |z|, which over an interval of
    /// the piece are linear in t, so g at the least (greatest) of each at the interval's
    /// ends bounds it from below (above). An interval both of whose ends lie outside is
    /// dropped where the lower bound is outside too, and one inside where the upper bound
    /// is; the rest are halved down to `1 / 2^DEPTH` of the piece and searched there as
    /// [`Superellipsoid::interval_hits`] does. False when `f` stopped.
    fn bounded_hits(&self, ray: &Ray, a: f64, b: f64, f: &mut impl FnMut(f64) -> bool) -> bool {
        // Depth first, nearest on top: at most one pending interval per level.
        let mut stack = [Interval::default(); DEPTH as usize + 2];
        stack[0] = Interval {
            t: (a, b),
            f: (self.along(ray, a), self.along(ray, b)),
            depth: 0,
        };
        let mut n = 1;
        while n > 0 {
            n -= 1;
            let i = stack[n];
            if self.without_crossing(ray, &i) {
                continue;
            }
            if i.depth == DEPTH {
                if !self.interval_hits(ray, &i, f) {
                    return false;
                }
                continue;
            }
            let tm = 0.5 * (i.t.0 + i.t.1);
            let fm = self.along(ray, tm);
            let depth = i.depth + 1;
            stack[n] = Interval {
                t: (tm, i.t.1),
                f: (fm, i.f.1),
                depth,
            };
            stack[n + 1] = Interval {
                t: (i.t.0, tm),
                f: (i.f.0, fm),
                depth,
            };
            n += 2;
        }
        true
    }

    /// Whether g's bounds over the interval ([`Superellipsoid::bounded_hits`]) keep it on
    /// its ends' side throughout. Each coordinate's least magnitude is lowered by a
    /// rounding margin: a piece's ends lie on the coordinate planes only to rounding.
    fn without_crossing(&self, ray: &Ray, i: &Interval) -> bool {
        let (outside, inside) = (i.f.0 > 0.0 && i.f.1 > 0.0, i.f.0 <= 0.0 && i.f.1 <= 0.0);
        if !outside && !inside {
            return false;
        }
        let (pa, pb) = (ray.at(i.t.0).abs(), ray.at(i.t.1).abs());
        if outside {
            let least = (pa.min(pb) - DVec3::splat(1e-12)).max(DVec3::ZERO);
            self.value(least) > 0.0
        } else {
            self.value(pa.max(pb)) <= 0.0
        }
    }

    /// Roots in an interval of the smallest size: a sign change between its ends, or,
    /// with both ends outside, a dip below zero between them (the slope falling then
    /// rising), found by searching the minimum. False when `f` stopped.
    fn interval_hits(&self, ray: &Ray, i: &Interval, f: &mut impl FnMut(f64) -> bool) -> bool {
        let ((a, b), (fa, fb)) = (i.t, i.f);
        let root = |lo: f64, hi: f64, flo: f64, fhi: f64| {
            illinois(|t| self.along(ray, t), lo, hi, flo, fhi, 1e-13)
        };
        if (fa <= 0.0) != (fb <= 0.0) {
            return f(root(a, b, fa, fb));
        }
        if fa <= 0.0 || self.slope(ray, a) >= 0.0 || self.slope(ray, b) <= 0.0 {
            return true;
        }
        let m = self.slope_root(ray, a, b);
        let fm = self.along(ray, m);
        if fm < 0.0 {
            return f(root(a, m, fa, fm)) && f(root(m, b, fm, fb));
        }
        true
    }

    /// The root of f in [a, b], where f changes sign (f(a) = fa).
    fn root(&self, ray: &Ray, a: f64, b: f64, fa: f64) -> f64 {
        let fb = self.along(ray, b);
        illinois(|t| self.along(ray, t), a, b, fa, fb, 1e-13)
    }

    /// The root of the slope in [a, b], where it rises from negative to positive.
    fn slope_root(&self, ray: &Ray, a: f64, b: f64) -> f64 {
        let (sa, sb) = (self.slope(ray, a), self.slope(ray, b));
        illinois(|t| self.slope(ray, t), a, b, sa, sb, 1e-10)
    }
}

/// Each of two magnitudes' share of the sum of their p-th powers, from w = (smaller /
/// larger)^p.
#[inline]
fn shares(a: f64, b: f64, w: f64) -> [f64; 2] {
    let larger = 1.0 / (1.0 + w);
    let smaller = w * larger;
    if a >= b {
        [larger, smaller]
    } else {
        [smaller, larger]
    }
}

/// share / |v| with v's sign: a power's derivative over the power (0 at v = 0, where it is
/// for exponents above 1).
#[inline]
fn per_unit(share: f64, v: f64) -> f64 {
    if v == 0.0 { 0.0 } else { share / v }
}

/// How close Newton's steps come to a root in [a, b]: as close as the bracketing search.
fn root_tolerance(a: f64, b: f64) -> f64 {
    1e-13 * (a.abs() + b.abs()).max(1e-10)
}

/// `x^e` for x >= 0, without `powf` where e is 1, 2 or 1/2 (a sphere's and the pinched
/// shapes' bounding hull's exponents and their inverses). Otherwise 2^(e log2 x): `powf`
/// took 240 instructions (glibc 2.36) and `log2` and `exp2` together 90, for a relative
/// error of about |e log2 x| 2^-52 (1e-14 where the power is 10^-30), far below what
/// the roots are found to.
#[inline]
fn power(x: f64, e: f64) -> f64 {
    if e == 1.0 {
        x
    } else if e == 2.0 {
        x * x
    } else if e == 0.5 {
        x.sqrt()
    } else {
        (e * x.log2()).exp2()
    }
}

/// Whether [`power`] takes `x^e` exactly, without logarithms.
fn exact_power(e: f64) -> bool {
    e == 1.0 || e == 2.0 || e == 0.5
}

/// The root of g in [a, b] where g changes sign (g(a) = ga, g(b) = gb): regula falsi with
/// the Illinois rule (the stale end's value halved), which converges superlinearly and never
/// leaves the bracket, and a bisection wherever two steps did not halve the bracket (with
/// exponents in the hundreds one end's value can be 10^10 times the other's, and halving it
/// takes dozens of steps); stops when the bracket is below `rel` of the span, or when a
/// step moves by next to nothing and g changes sign that close beside it.
fn illinois(
    g: impl Fn(f64) -> f64,
    mut a: f64,
    mut b: f64,
    mut ga: f64,
    mut gb: f64,
    rel: f64,
) -> f64 {
    let tol = rel * (a.abs() + b.abs()).max(1e-10);
    let mut side = 0;
    let mut t = 0.5 * (a + b);
    // The bracket's width one and two steps before.
    let mut widths = [f64::INFINITY; 2];
    for _ in 0..200 {
        let prev = t;
        let stalled = b - a > 0.5 * widths[1];
        widths = [b - a, widths[0]];
        t = if gb != ga && !stalled {
            (a * gb - b * ga) / (gb - ga)
        } else {
            0.5 * (a + b)
        };
        if !(t > a && t < b) {
            t = 0.5 * (a + b);
        }
        let gt = g(t);
        if gt == 0.0 {
            return t;
        }
        if (gt < 0.0) == (gb < 0.0) {
            b = t;
            gb = gt;
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        } else {
            a = t;
            ga = gt;
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        }
        if b - a <= tol {
            break;
        }
        if (t - prev).abs() <= tol * 0.01 {
            // Converged from one side, or stuck there: a look just beside t tells.
            let beside = if t == a { t + tol } else { t - tol };
            if beside > a && beside < b && (g(beside) < 0.0) != (gt < 0.0) {
                break;
            }
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hits(s: &Superellipsoid, ray: &Ray) -> Vec<f64> {
        let mut out = Vec::new();
        s.each_hit(ray, |t| {
            out.push(t);
            true
        });
        out
    }

    #[test]
    fn a_sphere_and_a_box() {
        // <1, 1> is the unit sphere.
        let s = Superellipsoid::new(1.0, 1.0);
        let h = hits(&s, &Ray::new(DVec3::new(0.6, 0.0, -5.0), DVec3::Z));
        assert_eq!(h.len(), 2);
        assert!(
            (h[0] - (5.0 - 0.8)).abs() < 1e-9 && (h[1] - 5.8).abs() < 1e-9,
            "{h:?}"
        );
        assert!(s.inside(DVec3::new(0.5, 0.5, 0.5)) && !s.inside(DVec3::new(0.6, 0.6, 0.6)));
        let g = s.gradient(DVec3::new(0.6, 0.0, 0.8));
        assert!((g.normalize() - DVec3::new(0.6, 0.0, 0.8)).length() < 1e-9);
        // Small exponents: nearly the cube.
        let b = Superellipsoid::new(0.05, 0.05);
        let h = hits(&b, &Ray::new(DVec3::new(0.5, 0.3, -5.0), DVec3::Z));
        assert_eq!(h.len(), 2);
        assert!(
            (h[0] - 4.0).abs() < 1e-3 && (h[1] - 6.0).abs() < 1e-3,
            "{h:?}"
        );
    }

    #[test]
    fn grazing_rays_meet_the_sphere() {
        let s = Superellipsoid::new(1.0, 1.0);
        for k in 2..=6 {
            let e = 10f64.powi(-k);
            let inside = Ray::new(DVec3::new(1.0 - e, 0.0, -5.0), DVec3::Z);
            let outside = Ray::new(DVec3::new(1.0 + e, 0.0, -5.0), DVec3::Z);
            assert_eq!(hits(&s, &inside).len(), 2, "k={k}");
            assert!(hits(&s, &outside).is_empty(), "k={k}");
        }
    }

    #[test]
    fn a_pinched_star() {
        // <3, 3>: concave faces. On the x axis the surface is at x = 1, on the diagonal
        // x = y = z where 3 x^(2/3) = 1, x = 3^(-3/2).
        let s = Superellipsoid::new(3.0, 3.0);
        let h = hits(&s, &Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X));
        assert!((h[0] - 4.0).abs() < 1e-9, "{h:?}");
        let d = DVec3::ONE.normalize();
        let h = hits(&s, &Ray::new(-5.0 * d, d));
        let x = 3f64.powf(-1.5);
        assert!((h[0] - (5.0 - x * 3f64.sqrt())).abs() < 1e-7, "{h:?}");
        // A ray parallel to x at height y = 0.3: in the xy plane |x|^(2/3) + |y|^(2/3) = 1.
        let h = hits(&s, &Ray::new(DVec3::new(-5.0, 0.3, 0.0), DVec3::X));
        assert_eq!(h.len(), 2, "{h:?}");
        let x = (1.0 - 0.3f64.powf(2.0 / 3.0)).powf(1.5);
        assert!((h[0] - (5.0 - x)).abs() < 1e-7, "{h:?}");
    }

    /// Newton's steps (convex shapes) and the search within the hull (pinched ones) find
    /// the crossings a dense sampling of g along random lines finds, at g's zeros.
    #[test]
    fn crossings_are_the_sign_changes_along_the_line() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64::seed_from_u64(7);
        let exponents = [
            0.001, 0.005, 0.02, 0.05, 0.1, 0.3, 0.7, 1.0, 1.6, 2.0, 2.5, 3.0,
        ];
        let (mut checked, mut crossings) = (0, 0);
        for _ in 0..1500 {
            let s = Superellipsoid::new(
                exponents[rng.random_range(0..exponents.len())],
                exponents[rng.random_range(0..exponents.len())],
            );
            let mut v = |r: f64| {
                DVec3::new(
                    rng.random_range(-r..r),
                    rng.random_range(-r..r),
                    rng.random_range(-r..r),
                )
            };
            let (origin, target) = (v(4.0), v(0.9));
            let ray = Ray::new(origin, target - origin);
            let steps = 16_000;
            let t_end = 4.0;
            let dt = t_end / f64::from(steps);
            let mut found = hits(&s, &ray);
            found.retain(|&t| t > dt && t < t_end);
            // Two crossings within a few steps (a grazing ray) would hide from the sampling.
            if found.windows(2).any(|w| w[1] - w[0] < 4.0 * dt) {
                continue;
            }
            let mut changes = 0;
            let mut last = s.value(ray.at(dt));
            for i in 2..=steps {
                let now = s.value(ray.at(dt * f64::from(i)));
                changes += usize::from((now <= 0.0) != (last <= 0.0));
                last = now;
            }
            assert_eq!(found.len(), changes, "{s:?} {ray:?}: {found:?}");
            for &t in &found {
                // A crossing: g - 1 changes sign within a billionth around it (a steep
                // g, exponents in the hundreds, leaves no value near 0 to test).
                let h = 1e-9 * (1.0 + t.abs());
                let (before, after) = (s.value(ray.at(t - h)), s.value(ray.at(t + h)));
                assert!(before * after <= 0.0, "{s:?} {ray:?}: {t}");
            }
            checked += 1;
            crossings += changes;
        }
        assert!(
            checked > 1400 && crossings > 1000,
            "{checked} rays, {crossings} crossings"
        );
    }

    /// A shape with each exponent's parameter uniform in [0.1, 4): pinched ones (above 2)
    /// and convex ones alike.
    fn random_shape(rng: &mut rand_pcg::Pcg64) -> Superellipsoid {
        use rand::RngExt;
        Superellipsoid::new(rng.random_range(0.1..4.0), rng.random_range(0.1..4.0))
    }

    /// A point uniform in the shapes' cube [-1, 1]^3.
    fn point_in_cube(rng: &mut rand_pcg::Pcg64) -> DVec3 {
        use rand::RngExt;
        DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        )
    }

    /// Within a piece of a line (no coordinate changing sign), g at every point of an
    /// interval lies between its values at the least and the greatest magnitudes of the
    /// interval's ends: the bounds the pinched shapes' search drops intervals by.
    #[test]
    fn g_lies_between_its_bounds_over_an_interval() {
        use rand::SeedableRng;
        let mut rng = rand_pcg::Pcg64::seed_from_u64(9);
        let mut checked = 0;
        for _ in 0..20_000 {
            let s = random_shape(&mut rng);
            let (a, b) = (point_in_cube(&mut rng), point_in_cube(&mut rng));
            if (a * b).min_element() < 0.0 {
                continue; // a coordinate changes sign between them
            }
            let (lo, hi) = (s.value(a.abs().min(b.abs())), s.value(a.abs().max(b.abs())));
            for k in 0..=16 {
                let g = s.value(a.lerp(b, f64::from(k) / 16.0));
                let slack = 1e-12 * (1.0 + g.abs());
                assert!(
                    lo <= g + slack && g <= hi + slack,
                    "{s:?} {a} {b}: {lo} {g} {hi}"
                );
            }
            checked += 1;
        }
        assert!(checked > 2_000, "{checked}");
    }

    /// The pinched shapes lie within the convex hull their search is narrowed to.
    #[test]
    fn pinched_shapes_lie_within_their_hull() {
        use rand::SeedableRng;
        let mut rng = rand_pcg::Pcg64::seed_from_u64(8);
        let mut inside = 0;
        for _ in 0..100_000 {
            let s = random_shape(&mut rng);
            let hull = s.hull();
            let q = point_in_cube(&mut rng);
            if s.value(q) <= 0.0 {
                inside += 1;
                assert!(hull.value(q) <= 1e-12, "{s:?} {q}");
            }
        }
        assert!(inside > 20_000, "{inside}");
    }
}
