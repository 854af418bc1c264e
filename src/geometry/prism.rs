//! The prism: closed spline curves in the x-z plane, filled by the even-odd rule, swept
//! along y (linear sweep) or towards the origin (conic sweep: the curves at height y are
//! the profile scaled by y). Every crossing is found, however many segments a ray passes,
//! without allocation.

use glam::{DVec2, DVec3};

use super::profile::Profile;
use super::roots::roots_in;
use super::{Aabb, Ray};
use crate::scene::Segment;
use crate::scene::spline::{evaluate, tangent};

#[derive(Clone, Debug, PartialEq)]
pub struct PrismData {
    pub profile: Profile,
    /// The heights, lowest first.
    pub y_lo: f64,
    pub y_hi: f64,
    pub conic: bool,
    pub open: bool,
    /// The bounds, a little larger: a line that misses them skips the segments. The BVH
    /// does this for a prism on its own, but not for the glyphs of a text inside CSG.
    reach: Aabb,
}

impl PrismData {
    pub fn new(segments: &[Segment], h1: f64, h2: f64, conic: bool, open: bool) -> PrismData {
        let mut p = PrismData {
            profile: Profile::new(segments),
            y_lo: h1.min(h2),
            y_hi: h1.max(h2),
            conic,
            open,
            reach: Aabb::new(DVec3::ZERO, DVec3::ZERO),
        };
        let b = p.bounds();
        let pad = DVec3::splat(1e-9 * (b.max - b.min).max_element());
        p.reach = Aabb::new(b.min - pad, b.max + pad);
        p
    }

    /// Whether the ray's whole line (both ways) meets the padded bounds.
    fn line_meets_reach(&self, ray: &Ray) -> bool {
        let inv = ray.direction.recip();
        let t1 = (self.reach.min - ray.origin) * inv;
        let t2 = (self.reach.max - ray.origin) * inv;
        // NaN (0 * inf, a line in a face's plane) loses to the other operand: conservative.
        t1.min(t2).max_element() <= t1.max(t2).min_element()
    }

    pub fn bounds(&self) -> Aabb {
        let at = |y: f64| {
            let s = if self.conic { y } else { 1.0 };
            Aabb::new(
                DVec3::new(self.profile.lo.x * s, y, self.profile.lo.y * s),
                DVec3::new(self.profile.hi.x * s, y, self.profile.hi.y * s),
            )
        };
        at(self.y_lo).union(&at(self.y_hi))
    }

    /// The profile point a point of the solid maps to (its x and z, divided by y when
    /// the sweep is conic).
    fn profile_point(&self, p: DVec3) -> DVec2 {
        let q = DVec2::new(p.x, p.z);
        if self.conic { q / p.y } else { q }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.y > self.y_lo && p.y < self.y_hi && self.profile.contains(self.profile_point(p))
    }

    /// Calls `f` with every crossing of the surface along the ray's line.
    pub fn each_hit(&self, ray: &Ray, mut f: impl FnMut(f64)) {
        if !self.line_meets_reach(ray) {
            return;
        }
        let (o, d) = (ray.origin, ray.direction);
        if !self.open && d.y != 0.0 {
            for h in [self.y_lo, self.y_hi] {
                if self.conic && h == 0.0 {
                    continue;
                }
                let t = (h - o.y) / d.y;
                let p = o + d * t;
                let scale = if self.conic { h } else { 1.0 };
                if self.profile.contains(DVec2::new(p.x, p.z) / scale) {
                    f(t);
                }
            }
        }
        if self.conic {
            self.conic_sides(ray, &mut f);
        } else {
            self.linear_sides(ray, &mut f);
        }
    }

    fn linear_sides(&self, ray: &Ray, f: &mut impl FnMut(f64)) {
        let (o, d) = (ray.origin, ray.direction);
        let (o2, d2) = (DVec2::new(o.x, o.z), DVec2::new(d.x, d.z));
        let dd = d2.length_squared();
        if dd == 0.0 {
            return;
        }
        // The line through the ray's footprint: n . (q - o2) = 0.
        let n = DVec2::new(d2.y, -d2.x);
        for seg in &self.profile.segments {
            if !seg.straddles(|q| n.dot(q - o2)) {
                continue;
            }
            let c = &seg.c;
            let poly = [n.dot(c[3]), n.dot(c[2]), n.dot(c[1]), n.dot(c[0] - o2)];
            for &s in roots_in(&poly, 0.0, 1.0).as_slice() {
                let t = (evaluate(c, s) - o2).dot(d2) / dd;
                let y = o.y + t * d.y;
                if y >= self.y_lo && y <= self.y_hi {
                    f(t);
                }
            }
        }
    }

    fn conic_sides(&self, ray: &Ray, f: &mut impl FnMut(f64)) {
        let (o, d) = (ray.origin, ray.direction);
        // The surface point (u, 1, v) y lies on the ray when (u, 1, v) is in the plane
        // through the origin holding the ray: n . (u, 1, v) = 0.
        let n = o.cross(d);
        if n == DVec3::ZERO {
            return;
        }
        for seg in &self.profile.segments {
            if !seg.straddles(|q| n.x * q.x + n.z * q.y + n.y) {
                continue;
            }
            let c = &seg.c;
            let k = |v: DVec2| n.x * v.x + n.z * v.y;
            let poly = [k(c[3]), k(c[2]), k(c[1]), k(c[0]) + n.y];
            for &s in roots_in(&poly, 0.0, 1.0).as_slice() {
                let q = evaluate(c, s);
                let w = DVec3::new(q.x, 1.0, q.y);
                let dw = d.cross(w);
                let denom = dw.length_squared();
                if denom == 0.0 {
                    continue;
                }
                let t = -o.cross(w).dot(dw) / denom;
                let y = o.y + t * d.y;
                if y >= self.y_lo && y <= self.y_hi {
                    f(t);
                }
            }
        }
    }

    /// The outward normal at a point on the surface: a cap's, or the side's at the nearest
    /// point of the profile.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let q = self.profile_point(p);
        let scale = if self.conic { p.y.abs() } else { 1.0 };
        let (dist, seg, s) = self.profile.nearest(q);
        if !self.open {
            let (below, above) = ((p.y - self.y_lo).abs(), (p.y - self.y_hi).abs());
            if below.min(above) < dist * scale || !q.is_finite() {
                return if below < above { -DVec3::Y } else { DVec3::Y };
            }
        }
        let Some(seg) = seg else {
            return DVec3::Y;
        };
        let c = &self.profile.segments[seg].c;
        let t = tangent(c, s);
        let mut n = if self.conic {
            let at = evaluate(c, s);
            DVec3::new(-t.y, t.y * at.x - t.x * at.y, t.x)
        } else {
            DVec3::new(t.y, 0.0, -t.x)
        };
        // Outward: a step along the normal leaves the filled profile.
        let m = DVec2::new(n.x, n.z).normalize_or_zero();
        let size = (self.profile.hi - self.profile.lo)
            .max_element()
            .max(1e-300);
        let step = if self.conic && p.y < 0.0 { -m } else { m };
        if self.profile.contains(q + step * (1e-7 * size)) {
            n = -n;
        }
        n
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{SplineKind, prism_profile};

    fn prism(kind: SplineKind, pts: &[(f64, f64)], conic: bool) -> PrismData {
        let pts: Vec<DVec2> = pts.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
        let profile = prism_profile(kind, &pts).unwrap();
        PrismData::new(&profile.segments, 0.0, 1.0, conic, false)
    }

    fn hits(p: &PrismData, o: DVec3, d: DVec3) -> Vec<f64> {
        let mut v = Vec::new();
        p.each_hit(&Ray::new(o, d), |t| v.push(t));
        v.sort_by(f64::total_cmp);
        v
    }

    const SQUARE_WITH_HOLE: [(f64, f64); 10] = [
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 4.0),
        (0.0, 4.0),
        (0.0, 0.0),
        (1.0, 1.0),
        (3.0, 1.0),
        (3.0, 3.0),
        (1.0, 3.0),
        (1.0, 1.0),
    ];

    #[test]
    fn linear_prism_sides_caps_and_hole() {
        let p = prism(SplineKind::Linear, &SQUARE_WITH_HOLE, false);
        // Along x through the hole: four side crossings.
        let t = hits(&p, DVec3::new(-5.0, 0.5, 2.0), DVec3::X);
        assert_eq!(t, vec![5.0, 6.0, 8.0, 9.0]);
        let n = p.normal(DVec3::new(0.0, 0.5, 2.0)).normalize();
        assert!((n + DVec3::X).length() < 1e-12, "{n}");
        let n = p.normal(DVec3::new(1.0, 0.5, 2.0)).normalize();
        assert!(
            (n - DVec3::X).length() < 1e-12,
            "the hole's wall faces into it: {n}"
        );
        // Down onto the top cap, and through the hole to nothing.
        let t = hits(&p, DVec3::new(0.5, 5.0, 0.5), -DVec3::Y);
        assert_eq!(t, vec![4.0, 5.0]);
        assert_eq!(p.normal(DVec3::new(0.5, 1.0, 0.5)), DVec3::Y);
        assert_eq!(p.normal(DVec3::new(0.5, 0.0, 0.5)), -DVec3::Y);
        assert!(hits(&p, DVec3::new(2.0, 5.0, 2.0), -DVec3::Y).is_empty());
        assert!(p.inside(DVec3::new(0.5, 0.5, 0.5)));
        assert!(!p.inside(DVec3::new(2.0, 0.5, 2.0)));
        assert!(!p.inside(DVec3::new(0.5, 1.5, 0.5)));
        let b = p.bounds();
        assert_eq!((b.min, b.max), (DVec3::ZERO, DVec3::new(4.0, 1.0, 4.0)));
    }

    #[test]
    fn a_comb_has_more_crossings_than_four() {
        // Six teeth along x: a ray through them crosses twelve walls.
        let mut pts = vec![(0.0, 0.0)];
        for k in 0..6 {
            let x = k as f64 * 2.0;
            pts.extend([
                (x + 1.0, 0.0),
                (x + 1.0, 2.0),
                (x + 2.0, 2.0),
                (x + 2.0, 0.0),
            ]);
        }
        pts.extend([(12.0, -1.0), (0.0, -1.0), (0.0, 0.0)]);
        let p = prism(SplineKind::Linear, &pts, false);
        assert_eq!(hits(&p, DVec3::new(-1.0, 0.5, 1.0), DVec3::X).len(), 12);
    }

    #[test]
    fn conic_pyramid() {
        let sq = [
            (-1.0, -1.0),
            (1.0, -1.0),
            (1.0, 1.0),
            (-1.0, 1.0),
            (-1.0, -1.0),
        ];
        let p = prism(SplineKind::Linear, &sq, true);
        assert!(p.inside(DVec3::new(0.25, 0.5, 0.0)));
        assert!(!p.inside(DVec3::new(0.75, 0.5, 0.0)));
        // At y = 0.5 the section is [-0.5, 0.5]^2.
        let t = hits(&p, DVec3::new(-5.0, 0.5, 0.0), DVec3::X);
        assert_eq!(t.len(), 2);
        assert!(
            (t[0] - 4.5).abs() < 1e-12 && (t[1] - 5.5).abs() < 1e-12,
            "{t:?}"
        );
        let n = p.normal(DVec3::new(-0.5, 0.5, 0.0)).normalize();
        let want = DVec3::new(-1.0, -1.0, 0.0).normalize();
        assert!((n - want).length() < 1e-12, "{n}");
        // The cap at y = 1 is the profile itself.
        let t = hits(&p, DVec3::new(0.9, 3.0, 0.9), -DVec3::Y);
        assert_eq!(t[0], 2.0);
        let b = p.bounds();
        assert_eq!((b.min, b.max), (DVec3::new(-1.0, 0.0, -1.0), DVec3::ONE));
    }

    #[test]
    fn curved_hits_lie_on_the_curve_with_perpendicular_normals() {
        let pts = [
            (-0.2, -1.0),
            (0.2, -1.0),
            (0.2, 0.2),
            (1.0, -0.2),
            (1.0, 0.2),
            (0.2, 1.0),
            (-0.2, 1.0),
            (-1.0, 0.2),
            (-1.0, -0.2),
            (-0.2, 0.2),
            (-0.2, -1.0),
            (0.2, -1.0),
            (0.2, 0.2),
        ];
        for conic in [false, true] {
            let p = prism(SplineKind::Cubic, &pts, conic);
            let mut found = 0;
            for k in 0..50 {
                let a = k as f64 * 0.37;
                let o = DVec3::new(3.0 * a.cos(), 0.6, 3.0 * a.sin());
                let d = DVec3::new(-a.cos() + 0.1, 0.05, -a.sin());
                for t in hits(&p, o, d) {
                    found += 1;
                    let x = o + d * t;
                    let q = p.profile_point(x);
                    let (dist, seg, s) = p.profile.nearest(q);
                    assert!(dist < 1e-9, "{conic} {k}: {dist}");
                    let tan = tangent(&p.profile.segments[seg.unwrap()].c, s);
                    let n = p.normal(x);
                    assert!(n.dot(DVec3::new(tan.x, 0.0, tan.y)).abs() < 1e-9 * n.length());
                    // Outward: just outside along the normal, just inside against it.
                    let step = n.normalize() * 1e-6;
                    assert!(!p.inside(x + step) && p.inside(x - step), "{conic} {k}");
                }
            }
            assert!(found > 100, "{found}");
        }
    }
}
