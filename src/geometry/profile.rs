//! 2-D spline curves, as prisms and lathes use them: each segment a cubic polynomial with
//! its bounding rectangle; the even-odd inside test and the nearest point on the curves.

use glam::DVec2;

use super::roots::roots_in;
use crate::scene::Segment;
use crate::scene::spline::evaluate;

/// A segment with its bounding rectangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfileSegment {
    pub c: Segment,
    pub lo: DVec2,
    pub hi: DVec2,
    /// Straight (the quadratic and cubic terms are zero).
    pub straight: bool,
}

impl ProfileSegment {
    pub fn new(c: Segment) -> ProfileSegment {
        let (lo, hi) = segment_bounds(&c);
        ProfileSegment {
            c,
            lo,
            hi,
            straight: c[2] == DVec2::ZERO && c[3] == DVec2::ZERO,
        }
    }

    /// Whether a linear function of points changes sign over the segment's rectangle.
    pub fn straddles(&self, g: impl Fn(DVec2) -> f64) -> bool {
        let corners = [
            self.lo,
            DVec2::new(self.hi.x, self.lo.y),
            DVec2::new(self.lo.x, self.hi.y),
            self.hi,
        ];
        let (mut pos, mut neg) = (false, false);
        for c in corners {
            let v = g(c);
            pos |= v >= 0.0;
            neg |= v <= 0.0;
        }
        pos && neg
    }
}

/// The exact bounding rectangle of a segment: its ends and the turning points inside.
fn segment_bounds(c: &Segment) -> (DVec2, DVec2) {
    let (a, b) = (evaluate(c, 0.0), evaluate(c, 1.0));
    let (mut lo, mut hi) = (a.min(b), a.max(b));
    for axis in 0..2 {
        let d = [3.0 * c[3][axis], 2.0 * c[2][axis], c[1][axis]];
        for &s in roots_in(&d, 0.0, 1.0).as_slice() {
            let p = evaluate(c, s);
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    (lo, hi)
}

/// Curves with their bounding rectangle.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    pub segments: Vec<ProfileSegment>,
    pub lo: DVec2,
    pub hi: DVec2,
}

impl Profile {
    pub fn new(segments: &[Segment]) -> Profile {
        let segments: Vec<ProfileSegment> =
            segments.iter().map(|&c| ProfileSegment::new(c)).collect();
        let lo = segments.iter().fold(DVec2::INFINITY, |a, s| a.min(s.lo));
        let hi = segments
            .iter()
            .fold(DVec2::NEG_INFINITY, |a, s| a.max(s.hi));
        Profile { segments, lo, hi }
    }

    pub fn memory_bytes(&self) -> usize {
        self.segments.capacity() * std::mem::size_of::<ProfileSegment>()
    }

    /// Even-odd rule: the parity of the curves' crossings by the half-line from `q`
    /// towards +x.
    pub fn contains(&self, q: DVec2) -> bool {
        if !(q.cmpge(self.lo).all() && q.cmple(self.hi).all()) {
            return false;
        }
        let mut inside = false;
        for seg in &self.segments {
            if q.y < seg.lo.y || q.y > seg.hi.y || q.x > seg.hi.x {
                continue;
            }
            let (a, b) = (seg.c[0], evaluate(&seg.c, 1.0));
            if seg.straight || q.x < seg.lo.x {
                // Wholly to the right, or straight: the parity is that of the ends.
                if (a.y > q.y) != (b.y > q.y) {
                    let x = if seg.straight {
                        a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x)
                    } else {
                        f64::INFINITY
                    };
                    if q.x < x {
                        inside = !inside;
                    }
                }
                continue;
            }
            let c = &seg.c;
            let poly = [c[3].y, c[2].y, c[1].y, c[0].y - q.y];
            for &s in roots_in(&poly, 0.0, 1.0).as_slice() {
                if s < 1.0 && evaluate(c, s).x > q.x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// Distance from `q` (a point on or next to the curves) to the nearest curve, with the
    /// segment and its parameter there.
    pub fn nearest(&self, q: DVec2) -> (f64, Option<usize>, f64) {
        let mut best = (f64::INFINITY, None, 0.0);
        for (i, seg) in self.segments.iter().enumerate() {
            let gap = (seg.lo - q).max(q - seg.hi).max(DVec2::ZERO).length();
            if gap >= best.0 {
                continue;
            }
            let c = &seg.c;
            let mut consider = |s: f64| {
                let dist = (evaluate(c, s) - q).length();
                if dist < best.0 {
                    best = (dist, Some(i), s);
                }
            };
            consider(0.0);
            consider(1.0);
            for axis in 0..2 {
                let poly = [c[3][axis], c[2][axis], c[1][axis], c[0][axis] - q[axis]];
                for &s in roots_in(&poly, 0.0, 1.0).as_slice() {
                    consider(s);
                }
            }
        }
        best
    }
}
