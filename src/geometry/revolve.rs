//! Shapes of revolution around the y axis: `sor` (r^2 a cubic of y, piece by piece, with
//! flat caps) and `lathe` (a 2-D spline curve <r, y> turned around the axis). Crossings are
//! found piece by piece, each piece culled by its slab of heights and its radius.

use glam::{DVec2, DVec3};

use super::profile::Profile;
use super::roots::{quadratic, roots_in, roots_in_wide};
use super::{Aabb, Ray};
use crate::scene::SorSegment;
use crate::scene::spline::tangent;

/// The ray's squared distance from the y axis as a t^2 + b t + c.
#[derive(Clone, Copy)]
struct AxisDistance {
    a: f64,
    b: f64,
    c: f64,
}

impl AxisDistance {
    fn of(o: DVec3, d: DVec3) -> AxisDistance {
        AxisDistance {
            a: d.x * d.x + d.z * d.z,
            b: 2.0 * (o.x * d.x + o.z * d.z),
            c: o.x * o.x + o.z * o.z,
        }
    }

    /// Whether the ray, for t in the slab [y0, y1], comes within `r` of the axis; the
    /// slab's t range.
    fn reaches(&self, o: DVec3, d: DVec3, y0: f64, y1: f64, r: f64) -> Option<(f64, f64)> {
        let (t0, t1) = if d.y != 0.0 {
            let (a, b) = ((y0 - o.y) / d.y, (y1 - o.y) / d.y);
            (a.min(b), a.max(b))
        } else if o.y >= y0 && o.y <= y1 {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            return None;
        };
        let t = if self.a > 0.0 {
            (-self.b / (2.0 * self.a)).clamp(t0, t1)
        } else {
            t0.clamp(-1e300, 1e300)
        };
        let nearest = (self.a * t + self.b) * t + self.c;
        (nearest <= r * r * (1.0 + 1e-9)).then_some((t0, t1))
    }
}

/// The ray moved along itself to its point nearest (0, `y_mid`, 0), so that polynomial
/// coefficients stay small for distant rays; the move, to add back to each t.
fn near_origin(ray: &Ray, y_mid: f64) -> (DVec3, f64) {
    let d = ray.direction;
    let rel = ray.origin - DVec3::new(0.0, y_mid, 0.0);
    let shift = -rel.dot(d) / d.length_squared().max(1e-300);
    (ray.origin + d * shift, shift)
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SorPiece {
    pub seg: SorSegment,
    pub r_max: f64,
}

#[derive(Clone, Debug, PartialEq)]
pub struct SorData {
    pub pieces: Vec<SorPiece>,
    pub y_lo: f64,
    pub y_hi: f64,
    /// The cap radii at y_lo and y_hi.
    pub r_lo: f64,
    pub r_hi: f64,
    pub r_max: f64,
    pub open: bool,
}

impl SorData {
    pub fn new(segments: &[SorSegment], open: bool) -> SorData {
        let pieces: Vec<SorPiece> = segments
            .iter()
            .map(|&seg| {
                // The largest r^2: at the ends or where the slope is zero.
                let mut m = seg.radius_squared(seg.h0).max(seg.radius_squared(seg.h1));
                let k = seg.k;
                for &u in roots_in(&[3.0 * k[3], 2.0 * k[2], k[1]], 0.0, seg.h1 - seg.h0).as_slice()
                {
                    m = m.max(seg.radius_squared(seg.h0 + u));
                }
                SorPiece {
                    seg,
                    r_max: m.max(0.0).sqrt(),
                }
            })
            .collect();
        let first = pieces.first().map_or(
            SorSegment {
                h0: 0.0,
                h1: 0.0,
                k: [0.0; 4],
            },
            |p| p.seg,
        );
        let last = pieces.last().map_or(first, |p| p.seg);
        SorData {
            y_lo: first.h0,
            y_hi: last.h1,
            r_lo: first.radius_squared(first.h0).max(0.0).sqrt(),
            r_hi: last.radius_squared(last.h1).max(0.0).sqrt(),
            r_max: pieces.iter().fold(0.0, |m, p| p.r_max.max(m)),
            pieces,
            open,
        }
    }

    pub fn bounds(&self) -> Aabb {
        let r = self.r_max;
        Aabb::new(DVec3::new(-r, self.y_lo, -r), DVec3::new(r, self.y_hi, r))
    }

    fn piece_at(&self, y: f64) -> &SorPiece {
        let i = self.pieces.partition_point(|p| p.seg.h1 < y);
        &self.pieces[i.min(self.pieces.len() - 1)]
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.y > self.y_lo
            && p.y < self.y_hi
            && p.x * p.x + p.z * p.z < self.piece_at(p.y).seg.radius_squared(p.y)
    }

    pub fn each_hit(&self, ray: &Ray, mut f: impl FnMut(f64)) {
        let (o, shift) = near_origin(ray, 0.5 * (self.y_lo + self.y_hi));
        let d = ray.direction;
        if !self.open && d.y != 0.0 {
            for (h, r) in [(self.y_lo, self.r_lo), (self.y_hi, self.r_hi)] {
                let t = (h - o.y) / d.y;
                let q = o + d * t;
                if q.x * q.x + q.z * q.z <= r * r {
                    f(t + shift);
                }
            }
        }
        let ad = AxisDistance::of(o, d);
        for piece in &self.pieces {
            let seg = &piece.seg;
            let Some((t0, t1)) = ad.reaches(o, d, seg.h0, seg.h1, piece.r_max) else {
                continue;
            };
            // r^2(e + t f) = a t^2 + b t + c, with e = o.y - h0 and f = d.y.
            let [k0, k1, k2, k3] = seg.k;
            let (e, g) = (o.y - seg.h0, d.y);
            let poly = [
                k3 * g * g * g,
                (3.0 * k3 * e + k2) * g * g - ad.a,
                (3.0 * k3 * e * e + 2.0 * k2 * e + k1) * g - ad.b,
                ((k3 * e + k2) * e + k1) * e + k0 - ad.c,
            ];
            for &t in roots_in(&poly, t0, t1).as_slice() {
                f(t + shift);
            }
        }
    }

    pub fn normal(&self, p: DVec3) -> DVec3 {
        let y = p.y.clamp(self.y_lo, self.y_hi);
        let seg = &self.piece_at(y).seg;
        let radial = p.x.hypot(p.z);
        if !self.open {
            let side = (radial - seg.radius_squared(y).max(0.0).sqrt()).abs();
            let (below, above) = ((p.y - self.y_lo).abs(), (p.y - self.y_hi).abs());
            if below.min(above) < side {
                return if below < above { -DVec3::Y } else { DVec3::Y };
            }
        }
        DVec3::new(2.0 * p.x, -seg.slope(y), 2.0 * p.z)
    }
}

/// A lathe: the profile in (r, y).
#[derive(Clone, Debug, PartialEq)]
pub struct LatheData {
    pub profile: Profile,
    pub r_max: f64,
}

impl LatheData {
    pub fn new(segments: &[crate::scene::Segment]) -> LatheData {
        let profile = Profile::new(segments);
        let r_max = profile.lo.x.abs().max(profile.hi.x.abs());
        LatheData { profile, r_max }
    }

    pub fn bounds(&self) -> Aabb {
        let r = self.r_max;
        Aabb::new(
            DVec3::new(-r, self.profile.lo.y, -r),
            DVec3::new(r, self.profile.hi.y, r),
        )
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.profile.contains(DVec2::new(p.x.hypot(p.z), p.y))
    }

    pub fn each_hit(&self, ray: &Ray, mut f: impl FnMut(f64)) {
        let mid = 0.5 * (self.profile.lo.y + self.profile.hi.y);
        let (o, shift) = near_origin(ray, mid);
        let d = ray.direction;
        let ad = AxisDistance::of(o, d);
        for seg in &self.profile.segments {
            let r = seg.lo.x.abs().max(seg.hi.x.abs());
            if ad.reaches(o, d, seg.lo.y, seg.hi.y, r).is_none() {
                continue;
            }
            let c = &seg.c;
            // Ascending coefficients of R(s) and of Y(s) - o.y.
            let rr = [c[0].x, c[1].x, c[2].x, c[3].x];
            let yy = [c[0].y - o.y, c[1].y, c[2].y, c[3].y];
            if d.y == 0.0 {
                let poly = [yy[3], yy[2], yy[1], yy[0]];
                for &s in roots_in(&poly, 0.0, 1.0).as_slice() {
                    let r = crate::scene::spline::evaluate(c, s).x;
                    for &t in quadratic(ad.a, ad.b, ad.c - r * r).as_slice() {
                        f(t + shift);
                    }
                }
                continue;
            }
            // a (Y - oy)^2 + b dy (Y - oy) + (c - R^2) dy^2 = 0: degree 6 in s.
            let (y2, r2) = (square(&yy), square(&rr));
            let g = d.y;
            let mut poly = [0.0; 7];
            for (k, slot) in poly.iter_mut().enumerate() {
                let i = 6 - k;
                let lin = if i < 4 { yy[i] } else { 0.0 };
                let cst = if i == 0 { ad.c } else { 0.0 };
                *slot = ad.a * y2[i] + ad.b * g * lin + (cst - r2[i]) * g * g;
            }
            for &s in roots_in_wide(&poly, 0.0, 1.0).as_slice() {
                let y = crate::scene::spline::evaluate(c, s).y;
                f((y - o.y) / g + shift);
            }
        }
    }

    pub fn normal(&self, p: DVec3) -> DVec3 {
        let radial = p.x.hypot(p.z);
        let q = DVec2::new(radial, p.y);
        let (_, seg, s) = self.profile.nearest(q);
        let Some(seg) = seg else {
            return DVec3::Y;
        };
        let t = tangent(&self.profile.segments[seg].c, s);
        let mut n2 = DVec2::new(t.y, -t.x).normalize_or_zero();
        let size = (self.profile.hi - self.profile.lo)
            .max_element()
            .max(1e-300);
        if self.profile.contains(q + n2 * (1e-7 * size)) {
            n2 = -n2;
        }
        let out = if radial > 0.0 {
            DVec3::new(p.x / radial, 0.0, p.z / radial)
        } else {
            DVec3::ZERO
        };
        out * n2.x + DVec3::Y * n2.y
    }
}

/// The square of a cubic, ascending coefficients.
fn square(p: &[f64; 4]) -> [f64; 7] {
    let mut out = [0.0; 7];
    for i in 0..4 {
        for j in 0..4 {
            out[i + j] += p[i] * p[j];
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{SplineKind, lathe_profile, sor_profile};

    fn pts(p: &[(f64, f64)]) -> Vec<DVec2> {
        p.iter().map(|&(x, y)| DVec2::new(x, y)).collect()
    }

    fn hits(each: impl Fn(&Ray, &mut dyn FnMut(f64)), o: DVec3, d: DVec3) -> Vec<f64> {
        let mut v = Vec::new();
        each(&Ray::new(o, d), &mut |t| v.push(t));
        v.sort_by(f64::total_cmp);
        v
    }

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9)
    }

    #[test]
    fn sor_as_a_cylinder() {
        let p = pts(&[(1.0, -1.0), (1.0, 0.0), (1.0, 1.0), (1.0, 2.0)]);
        let segs = sor_profile(&p).unwrap();
        for open in [false, true] {
            let s = SorData::new(&segs, open);
            let each = |r: &Ray, f: &mut dyn FnMut(f64)| s.each_hit(r, f);
            let t = hits(each, DVec3::new(-5.0, 0.5, 0.0), DVec3::X);
            assert!(close(&t, &[4.0, 6.0]), "{t:?}");
            let n = s.normal(DVec3::new(-1.0, 0.5, 0.0)).normalize();
            assert!((n + DVec3::X).length() < 1e-12, "{n}");
            let t = hits(each, DVec3::new(0.3, 5.0, 0.0), -DVec3::Y);
            if open {
                assert!(t.is_empty());
            } else {
                assert!(close(&t, &[4.0, 5.0]), "{t:?}");
                assert_eq!(s.normal(DVec3::new(0.3, 1.0, 0.0)), DVec3::Y);
            }
            assert!(s.inside(DVec3::new(0.0, 0.5, 0.0)));
            assert!(!s.inside(DVec3::new(0.0, 1.5, 0.0)));
            let b = s.bounds();
            assert_eq!((b.min, b.max), (DVec3::new(-1.0, 0.0, -1.0), DVec3::ONE));
        }
    }

    #[test]
    fn sor_hits_lie_on_the_surface() {
        let p = pts(&[
            (0.2, -0.3),
            (0.5, 0.1),
            (0.9, 0.6),
            (0.3, 1.2),
            (0.6, 1.8),
            (1.0, 2.5),
        ]);
        let s = SorData::new(&sor_profile(&p).unwrap(), false);
        let mut found = 0;
        for k in 0..60 {
            let a = k as f64 * 0.41;
            let o = DVec3::new(4.0 * a.cos(), 0.9 + 0.3 * a.sin(), 40.0 * a.sin());
            let d = DVec3::new(0.0, 1.0 - 0.05 * k as f64 * 0.6, 0.0) - o;
            for t in hits(|r, f| s.each_hit(r, f), o, d) {
                found += 1;
                let x = o + d * t;
                let on_side = s.piece_at(x.y).seg.radius_squared(x.y) - (x.x * x.x + x.z * x.z);
                let on_cap = (x.y - s.y_lo).abs().min((x.y - s.y_hi).abs());
                assert!(
                    on_side.abs() < 1e-9 || on_cap < 1e-9,
                    "{k}: {on_side} {on_cap}"
                );
                let step = s.normal(x).normalize() * 1e-6;
                assert!(!s.inside(x + step) && s.inside(x - step), "{k}");
            }
        }
        assert!(found > 40, "{found}");
    }

    #[test]
    fn lathe_ring_with_a_square_section() {
        let p = pts(&[(0.5, 0.0), (0.8, 0.0), (0.8, 0.4), (0.5, 0.4), (0.5, 0.0)]);
        let l = LatheData::new(&lathe_profile(SplineKind::Linear, &p).unwrap());
        let each = |r: &Ray, f: &mut dyn FnMut(f64)| l.each_hit(r, f);
        // Horizontal, and slightly tilted through the same points.
        let t = hits(each, DVec3::new(-5.0, 0.2, 0.0), DVec3::X);
        assert!(close(&t, &[4.2, 4.5, 5.5, 5.8]), "{t:?}");
        let t = hits(each, DVec3::new(-5.0, 0.1, 0.0), DVec3::new(1.0, 0.02, 0.0));
        assert!(close(&t, &[4.2, 4.5, 5.5, 5.8]), "{t:?}");
        let n = l.normal(DVec3::new(-0.8, 0.2, 0.0)).normalize();
        assert!((n + DVec3::X).length() < 1e-12, "{n}");
        let n = l.normal(DVec3::new(-0.5, 0.2, 0.0)).normalize();
        assert!((n - DVec3::X).length() < 1e-12, "faces the hole: {n}");
        let t = hits(each, DVec3::new(0.0, 5.0, 0.65), -DVec3::Y);
        assert!(close(&t, &[4.6, 5.0]), "{t:?}");
        assert!((l.normal(DVec3::new(0.0, 0.4, 0.65)).normalize() - DVec3::Y).length() < 1e-12);
        assert!(l.inside(DVec3::new(0.0, 0.2, -0.65)));
        assert!(!l.inside(DVec3::new(0.0, 0.2, 0.0)));
        let b = l.bounds();
        assert_eq!(b.min, DVec3::new(-0.8, 0.0, -0.8));
        assert_eq!(b.max, DVec3::new(0.8, 0.4, 0.8));
    }

    #[test]
    fn curved_lathe_hits_lie_on_the_curve() {
        let p = pts(&[
            (0.1, -0.2),
            (0.2, 0.0),
            (0.5, 0.4),
            (0.2, 0.8),
            (0.2, 0.0),
            (0.5, 0.4),
        ]);
        for kind in [SplineKind::Quadratic, SplineKind::Cubic] {
            let l = LatheData::new(&lathe_profile(kind, &p).unwrap());
            let mut found = 0;
            for k in 0..60 {
                let a = k as f64 * 0.37;
                let o = DVec3::new(3.0 * a.cos(), 0.4 + a.sin(), 3.0 * a.sin());
                let mut d = DVec3::new(0.1 * a.sin(), 0.3, 0.0) - o;
                if k % 10 == 0 {
                    d.y = 0.0;
                }
                for t in hits(|r, f| l.each_hit(r, f), o, d) {
                    found += 1;
                    let x = o + d * t;
                    let (dist, _, _) = l.profile.nearest(DVec2::new(x.x.hypot(x.z), x.y));
                    assert!(dist < 1e-8, "{kind:?} {k}: {dist}");
                }
            }
            assert!(found > 100, "{found}");
        }
    }
}
