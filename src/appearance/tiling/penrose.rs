//! `tiling 26` and `tiling 27`: Penrose's kites and darts (P2) and rhombs (P3), the
//! tilings that are five-fold symmetric about the origin. Measured: edges of length 1
//! (a kite's long edge, a rhomb's edge); 26 is the infinite sun (five kites meet at the
//! origin at their 72-degree tips, their axes along 0, +-72 and +-144 degrees), kites type
//! 0 and darts type 1, bevelled over 1 / 4.46; 27 has five thick rhombs meeting at the
//! origin at their 72-degree corners (edges leave it along the same directions), thick
//! rhombs type 0 and thin ones type 1, bevelled over 1 / 3.43009.
//!
//! Neither tiling is periodic, so the tile holding a point is found by deflation: a wheel
//! of ten acute Robinson half-tiles round the origin, large enough to hold the point, is
//! cut into halves 1 / phi the size level by level, following only the half that holds the
//! point. Each deflation turns the centre's configuration, and it comes back every fourth
//! cut: POV-Ray's values (tests/tiling_values.rs) are matched at every one of 1600 points
//! by 8, 12 or 16 cuts for the kites and 9, 13 or 17 for the rhombs, and by no other count
//! between 7 and 17.

use glam::DVec2;

const PHI: f64 = 1.618_033_988_749_895;

/// Which of the two tilings.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Penrose {
    KitesAndDarts,
    Rhombs,
}

impl Penrose {
    /// The bevel width (measured to 1e-5; not an inradius).
    fn bevel(self) -> f64 {
        match self {
            Penrose::KitesAndDarts => 1.0 / 4.46,
            Penrose::Rhombs => 1.0 / 3.43009,
        }
    }

    /// The fewest cuts, and the step between counts that give the same tiling.
    fn cuts(self) -> (i32, i32) {
        match self {
            Penrose::KitesAndDarts => (8, 4),
            Penrose::Rhombs => (9, 4),
        }
    }
}

/// A Robinson half-tile: `acute` halves have 36 degrees at `apex`, the others 108. For
/// the rhombs, a tile is the half and its apex mirrored across the base `b`-`c`; for the
/// kites and darts, the half and `c` mirrored across the leg `apex`-`b` (a kite's axis
/// runs from its tip `apex` to `b`, a dart's from its reflex corner `apex` to its tip `b`).
#[derive(Clone, Copy)]
struct Half {
    acute: bool,
    apex: DVec2,
    b: DVec2,
    c: DVec2,
}

fn half(acute: bool, apex: DVec2, b: DVec2, c: DVec2) -> Half {
    Half { acute, apex, b, c }
}

impl Half {
    fn holds(&self, p: DVec2) -> bool {
        triangle_holds([self.apex, self.b, self.c], p)
    }

    /// The next level's halves that make up this one.
    fn cut(&self, tiling: Penrose) -> ([Half; 3], usize) {
        let (a, b, c) = (self.apex, self.b, self.c);
        match (tiling, self.acute) {
            (Penrose::Rhombs, true) => {
                let p = a + (b - a) / PHI;
                (
                    [
                        half(true, c, p, b),
                        half(false, p, c, a),
                        half(false, p, c, a),
                    ],
                    2,
                )
            }
            (Penrose::Rhombs, false) => {
                let q = b + (a - b) / PHI;
                let r = b + (c - b) / PHI;
                let parts = [
                    half(false, r, c, a),
                    half(false, q, r, b),
                    half(true, r, q, a),
                ];
                (parts, 3)
            }
            // A half-kite: two half-kites with their tip at its side corner and a half-dart
            // at its tip.
            (Penrose::KitesAndDarts, true) => {
                let d = a + (b - a) / PHI;
                let e = c + (a - c) / PHI;
                (
                    [
                        half(true, c, d, b),
                        half(true, c, d, e),
                        half(false, e, a, d),
                    ],
                    3,
                )
            }
            // A half-dart: a half-kite with its tip at the dart's, and a half-dart.
            (Penrose::KitesAndDarts, false) => {
                let f = b + (c - b) / PHI;
                (
                    [
                        half(true, b, a, f),
                        half(false, f, c, a),
                        half(false, f, c, a),
                    ],
                    2,
                )
            }
        }
    }
}

/// The value of a Penrose tiling at `(x, z)`.
pub(super) fn penrose_value(tiling: Penrose, p: DVec2) -> f64 {
    let h = locate(tiling, p);
    let depth = match tiling {
        Penrose::Rhombs => {
            let far = mirror(h.apex, h.b, h.c);
            polygon_depth(&[h.apex, h.b, far, h.c], p)
        }
        Penrose::KitesAndDarts if h.acute => {
            let side = mirror(h.c, h.apex, h.b);
            polygon_depth(&[h.apex, h.c, h.b, side], p)
        }
        Penrose::KitesAndDarts => dart_depth(h, p),
    };
    let kind = match (tiling, h.acute) {
        (Penrose::KitesAndDarts, true) | (Penrose::Rhombs, false) => 0.0,
        _ => 1.0,
    };
    (kind + (1.0 - depth / tiling.bevel()).max(super::BODY)) / 2.0
}

/// A dart's depth, measured as POV-Ray measures it: the dart is two overlapping acute
/// triangles (the tip, one wing, and where the line from that wing through the reflex
/// corner meets the far long edge), and the depth is the larger of the point's distances
/// to the edges of the triangles that hold it (checked on 1600 points).
fn dart_depth(h: Half, p: DVec2) -> f64 {
    let (reflex, tip, wing) = (h.apex, h.b, h.c);
    let other = mirror(wing, reflex, tip);
    let one = [tip, wing, crossing(wing, reflex, tip, other)];
    let two = [tip, other, crossing(other, reflex, tip, wing)];
    [one, two]
        .iter()
        .filter(|t| triangle_holds(**t, p))
        .map(|t| polygon_depth(t, p))
        .fold(0.0, f64::max)
}

/// Where the line through `a` and `b` meets the line through `c` and `d`.
fn crossing(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> DVec2 {
    let (u, v) = (b - a, d - c);
    a + u * ((c - a).perp_dot(v) / u.perp_dot(v))
}

/// `q` mirrored across the line through `s` and `e`.
fn mirror(q: DVec2, s: DVec2, e: DVec2) -> DVec2 {
    let line = e - s;
    let foot = s + line * ((q - s).dot(line) / line.length_squared());
    2.0 * foot - q
}

fn triangle_holds(t: [DVec2; 3], p: DVec2) -> bool {
    let side = |s: DVec2, e: DVec2| (e - s).perp_dot(p - s);
    let d = [side(t[0], t[1]), side(t[1], t[2]), side(t[2], t[0])];
    !(d.iter().any(|&x| x < 0.0) && d.iter().any(|&x| x > 0.0))
}

/// The distance from `p` to the nearest edge of a closed polygon.
fn polygon_depth(corners: &[DVec2], p: DVec2) -> f64 {
    let n = corners.len();
    (0..n)
        .map(|i| super::segment_distance(p, corners[i], corners[(i + 1) % n]))
        .fold(f64::INFINITY, f64::min)
}

/// The smallest half-tile (edge 1) holding `p`.
fn locate(tiling: Penrose, p: DVec2) -> Half {
    let (mut cuts, step) = tiling.cuts();
    let reach = (std::f64::consts::PI / 10.0).cos();
    while PHI.powi(cuts) * reach < p.length() + 3.0 {
        cuts += step;
    }
    let mut h = wheel(PHI.powi(cuts), p);
    for _ in 0..cuts {
        let (parts, n) = h.cut(tiling);
        // A point on a shared edge may test inside two parts; either is the same tile's.
        h = parts[..n]
            .iter()
            .copied()
            .find(|q| q.holds(p))
            .unwrap_or(parts[0]);
    }
    h
}

/// The wheel's half holding `p`: ten acute halves round the origin, mirrored in turn,
/// turned so that the edges leave the origin along the measured directions.
fn wheel(size: f64, p: DVec2) -> Half {
    let turn = -std::f64::consts::PI / 10.0;
    let at = |k: i32| DVec2::from_angle(f64::from(k) * std::f64::consts::PI / 10.0 + turn) * size;
    let nth = |i: i32| {
        let (b, c) = (at(2 * i - 1), at(2 * i + 1));
        let (b, c) = if i % 2 == 0 { (c, b) } else { (b, c) };
        half(true, DVec2::ZERO, b, c)
    };
    (0..10)
        .map(nth)
        .find(|h| h.holds(p))
        .unwrap_or_else(|| nth(0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Far from the origin the wheel grows (more cuts), and every point still lands in a
    /// half-tile of edge 1 that holds it.
    #[test]
    fn far_points_land_in_unit_halves() {
        for tiling in [Penrose::KitesAndDarts, Penrose::Rhombs] {
            for (i, r) in [0.3, 7.0, 150.0, 4e3, 1e5].into_iter().enumerate() {
                let p = DVec2::from_angle(0.7 + i as f64) * r;
                let h = locate(tiling, p);
                assert!(h.holds(p), "{p}");
                // The longest side of an acute half and of a rhomb's obtuse half is 1 or
                // phi; a dart half's is 1.
                let longest = [h.b - h.apex, h.c - h.apex, h.c - h.b]
                    .iter()
                    .map(|v| v.length())
                    .fold(0.0, f64::max);
                let expected: &[f64] = match tiling {
                    Penrose::KitesAndDarts => &[1.0],
                    Penrose::Rhombs => &[1.0, PHI],
                };
                let tol = 1e-6 * (1.0 + r);
                assert!(
                    expected.iter().any(|e| (longest - e).abs() < tol),
                    "{longest} at {p}"
                );
                let v = penrose_value(tiling, p);
                assert!((0.0..=1.0).contains(&v), "{v}");
            }
        }
    }

    /// The infinite sun: the five kites round the origin (type 0), a dart beyond the
    /// side corner at (-1, 0), with its tip at (-phi, 0) (measured).
    #[test]
    fn the_kites_make_a_sun_at_the_origin() {
        for k in 0..5 {
            let axis = DVec2::from_angle(f64::from(k) * 0.4 * std::f64::consts::PI);
            assert!(penrose_value(Penrose::KitesAndDarts, axis * 0.5) < 0.5);
        }
        assert!(penrose_value(Penrose::KitesAndDarts, DVec2::new(-1.3, 0.01)) > 0.5);
    }
}
