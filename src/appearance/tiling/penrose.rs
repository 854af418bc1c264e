//! `tiling 27`: Penrose's rhombs (P3), the tiling that is five-fold symmetric about the
//! origin with five thick rhombs meeting there at their 72-degree corners (measured: edges
//! leave the origin at 0, +-72 and +-144 degrees, edge length 1, thick rhombs type 0 and
//! thin ones type 1, both bevelled over 1 / 3.43009).
//!
//! The tiling is not periodic, so the tile holding a point is found by deflation: a wheel
//! of ten Robinson half-rhombs round the origin, large enough to hold the point, is cut
//! into smaller half-rhombs level by level (golden-ratio subdivision), following only the
//! piece that holds the point. A rhomb is its half and that half mirrored across its base.
//! Shallow wheels do not give the infinite tiling near the origin, and an even number of
//! cuts gives a different one away from it: POV-Ray's values (tests/tiling_values.rs) are
//! matched at every one of 1600 points by an odd number of at least 9 cuts.

use glam::DVec2;

const PHI: f64 = 1.618_033_988_749_895;

/// The bevel width of both rhombs (measured to 1e-5: not an inradius).
const BEVEL: f64 = 1.0 / 3.43009;

/// A Robinson half-rhomb: `thin` halves (36 degrees at `apex`) pair into thin rhombs,
/// the others (108 degrees at `apex`) into thick ones; `b` and `c` end the base.
#[derive(Clone, Copy)]
struct Half {
    thin: bool,
    apex: DVec2,
    b: DVec2,
    c: DVec2,
}

impl Half {
    fn holds(&self, p: DVec2) -> bool {
        let side = |s: DVec2, e: DVec2| (e - s).perp_dot(p - s);
        let (d1, d2, d3) = (
            side(self.apex, self.b),
            side(self.b, self.c),
            side(self.c, self.apex),
        );
        let negative = d1 < 0.0 || d2 < 0.0 || d3 < 0.0;
        let positive = d1 > 0.0 || d2 > 0.0 || d3 > 0.0;
        !(negative && positive)
    }

    /// The next level's halves (each 1 / phi the size) that make up this one.
    fn cut(&self) -> ([Half; 3], usize) {
        let (a, b, c) = (self.apex, self.b, self.c);
        let half = |thin, apex, b, c| Half { thin, apex, b, c };
        if self.thin {
            let p = a + (b - a) / PHI;
            (
                [
                    half(true, c, p, b),
                    half(false, p, c, a),
                    half(false, p, c, a),
                ],
                2,
            )
        } else {
            let q = b + (a - b) / PHI;
            let r = b + (c - b) / PHI;
            (
                [
                    half(false, r, c, a),
                    half(false, q, r, b),
                    half(true, r, q, a),
                ],
                3,
            )
        }
    }
}

/// The Penrose rhomb tiling's value at `(x, z)`.
pub(super) fn rhomb_value(p: DVec2) -> f64 {
    let h = locate(p);
    // The rhomb: the half and its apex mirrored across the base.
    let base = h.c - h.b;
    let foot = h.b + base * ((h.apex - h.b).dot(base) / base.length_squared());
    let far = 2.0 * foot - h.apex;
    let corners = [h.apex, h.b, far, h.c];
    let d = (0..4)
        .map(|i| segment_distance(p, corners[i], corners[(i + 1) % 4]))
        .fold(f64::INFINITY, f64::min);
    let kind = if h.thin { 1.0 } else { 0.0 };
    (kind + (1.0 - d / BEVEL).max(super::BODY)) / 2.0
}

fn segment_distance(p: DVec2, s: DVec2, e: DVec2) -> f64 {
    let edge = e - s;
    let t = ((p - s).dot(edge) / edge.length_squared()).clamp(0.0, 1.0);
    (s + edge * t).distance(p)
}

/// The smallest half-rhomb (edge 1) holding `p`.
fn locate(p: DVec2) -> Half {
    let r = p.length();
    let mut levels = 9;
    while PHI.powi(levels) * (std::f64::consts::PI / 10.0).cos() < r + 3.0 {
        levels += 2;
    }
    let size = PHI.powi(levels);
    let mut h = wheel(size, p);
    for _ in 0..levels {
        let (parts, n) = h.cut();
        // A point on a shared edge may test inside two parts; either is the same tile's.
        h = parts[..n]
            .iter()
            .copied()
            .find(|q| q.holds(p))
            .unwrap_or(parts[0]);
    }
    h
}

/// The wheel's thin half holding `p`: ten halves round the origin, mirrored in turn,
/// turned so that the rhombs' edges leave the origin along the measured directions.
fn wheel(size: f64, p: DVec2) -> Half {
    let turn = -std::f64::consts::PI / 10.0;
    let at = |k: f64| DVec2::from_angle(k * std::f64::consts::PI / 10.0 + turn) * size;
    let half = |i: i32| {
        let (mut b, mut c) = (at(f64::from(2 * i - 1)), at(f64::from(2 * i + 1)));
        if i % 2 == 0 {
            std::mem::swap(&mut b, &mut c);
        }
        Half {
            thin: true,
            apex: DVec2::ZERO,
            b,
            c,
        }
    };
    (0..10)
        .map(half)
        .find(|h| h.holds(p))
        .unwrap_or_else(|| half(0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Far from the origin the wheel grows (more cuts), and every point still lands in a
    /// rhomb of edge 1 that holds it.
    #[test]
    fn far_points_land_in_unit_rhombs() {
        for (i, r) in [0.3, 7.0, 150.0, 4e3, 1e5].into_iter().enumerate() {
            let p = DVec2::from_angle(0.7 + i as f64) * r;
            let h = locate(p);
            assert!(h.holds(p), "{p}");
            let legs = [(h.b - h.apex).length(), (h.c - h.apex).length()];
            for leg in legs {
                assert!((leg - 1.0).abs() < 1e-6 * (1.0 + r), "edge {leg} at {p}");
            }
            let v = rhomb_value(p);
            assert!((0.0..=1.0).contains(&v), "{v}");
        }
    }
}
