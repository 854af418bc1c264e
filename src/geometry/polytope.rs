//! The box around an intersection of half-spaces: POV-Ray's scenes cut solids from turned
//! planes (objectmods/thingy.inc's pyramid is six tilted planes and a floor), whose
//! half-spaces have no box of their own, so the intersection was tested by every ray in
//! the scene. The polytope's vertices bound it: each is where three of the planes meet
//! and lies inside all the others.

use glam::DVec3;

use super::Aabb;

/// A half-space n.x <= d with n of unit length.
#[derive(Clone, Copy, Debug)]
pub struct HalfSpace {
    pub normal: DVec3,
    pub distance: f64,
}

impl HalfSpace {
    /// The half-space n.x <= d for any non-zero n.
    pub fn new(normal: DVec3, distance: f64) -> HalfSpace {
        let length = normal.length();
        HalfSpace {
            normal: normal / length,
            distance: distance / length,
        }
    }

    /// Its complement's closure, n.x >= d.
    pub fn flipped(self) -> HalfSpace {
        HalfSpace {
            normal: -self.normal,
            distance: -self.distance,
        }
    }
}

/// More half-spaces than this are left unbounded (their triples grow as the cube).
pub const MOST_HALF_SPACES: usize = 24;

/// How far past the half-spaces' own offsets the search looks for vertices, as a
/// multiple of the largest: a side whose vertices reach that far is taken as open.
const REACH: f64 = 1e6;

/// Triples whose normals are nearer coplanar than this are passed over: their crossing
/// is too ill-determined to bound anything, and a vertex where they meet is also found
/// from better-conditioned triples of the planes that hold it.
const LEAST_DETERMINANT: f64 = 1e-9;

/// The box around the points inside every half-space and `within`, each side infinite
/// where the polytope reaches past the search's reach that way; `within` where there are
/// too many half-spaces or the polytope looks empty (the box then stays as it was).
pub fn polytope_extent(half_spaces: &[HalfSpace], within: Aabb) -> Aabb {
    if half_spaces.len() > MOST_HALF_SPACES {
        return within;
    }
    let scale = half_spaces
        .iter()
        .map(|h| h.distance.abs())
        .chain(box_sides(&within, 1.0).map(|h| h.distance.abs()))
        .fold(1.0, f64::max);
    let reach = REACH * scale;
    // The box's finite sides, and a cube of the search's reach closing the rest.
    let mut all: Vec<HalfSpace> = half_spaces.to_vec();
    all.extend(box_sides(&within, reach));
    // Each vertex grown by its rounding error.
    let mut found = Aabb::EMPTY;
    for i in 0..all.len() {
        for j in i + 1..all.len() {
            for k in j + 1..all.len() {
                if let Some((v, e)) = vertex(&all, [i, j, k], scale) {
                    found = found.union(&Aabb::new(v - e, v + e));
                }
            }
        }
    }
    if found.is_empty() {
        return within;
    }
    let open = |c: f64, side: f64| {
        if c.abs() >= 0.5 * reach {
            side * f64::INFINITY
        } else {
            c
        }
    };
    let extent = Aabb {
        min: DVec3::from_array(found.min.to_array().map(|c| open(c, -1.0))),
        max: DVec3::from_array(found.max.to_array().map(|c| open(c, 1.0))),
    };
    extent.intersection(&within)
}

/// The box's sides as half-spaces, its open sides closed at `reach` from the origin.
fn box_sides(b: &Aabb, reach: f64) -> impl Iterator<Item = HalfSpace> {
    let (min, max) = (b.min.to_array(), b.max.to_array());
    (0..3).flat_map(move |axis| {
        let unit = DVec3::AXES[axis];
        let upper = if max[axis].is_finite() {
            max[axis]
        } else {
            reach
        };
        let lower = if min[axis].is_finite() {
            min[axis]
        } else {
            -reach
        };
        [HalfSpace::new(unit, upper), HalfSpace::new(-unit, -lower)]
    })
}

/// Where the three half-spaces' planes meet, if that point lies inside every half-space,
/// with a bound on its rounding error (in every coordinate).
fn vertex(all: &[HalfSpace], [i, j, k]: [usize; 3], scale: f64) -> Option<(DVec3, f64)> {
    let (a, b, c) = (all[i], all[j], all[k]);
    let (bc, ca, ab) = (
        b.normal.cross(c.normal),
        c.normal.cross(a.normal),
        a.normal.cross(b.normal),
    );
    let det = a.normal.dot(bc);
    if det.abs() < LEAST_DETERMINANT {
        return None;
    }
    let v = (bc * a.distance + ca * b.distance + ab * c.distance) / det;
    // Cramer's rule's error: a few roundings of each term, over the determinant's.
    let size = a.distance.abs() + b.distance.abs() + c.distance.abs() + v.abs().max_element();
    let error = 1e-13 * (size + scale) / det.abs();
    let inside = all
        .iter()
        .all(|h| h.normal.dot(v) <= h.distance + error + 1e-12 * (scale + v.abs().max_element()));
    inside.then_some((v, error))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    fn pyramid() -> Vec<HalfSpace> {
        // Six planes tilted from the vertical, apex at height 2, and the floor y >= 0.
        let mut planes: Vec<HalfSpace> = (0..6)
            .map(|k| {
                let a = f64::from(k) * std::f64::consts::TAU / 6.0;
                let n = DVec3::new(a.cos() * 2.0, 1.0, a.sin() * 2.0);
                HalfSpace::new(n, 2.0)
            })
            .collect();
        planes.push(HalfSpace::new(DVec3::Y, 0.0).flipped());
        planes
    }

    #[test]
    fn a_pyramid_s_box_is_its_base_and_apex() {
        let b = polytope_extent(&pyramid(), Aabb::INFINITE);
        assert!(
            (b.max.y - 2.0).abs() < 1e-9 && b.min.y.abs() < 1e-9,
            "{b:?}"
        );
        assert!(
            (b.max.x - 1.0).abs() < 1e-9 && (b.min.x + 1.0).abs() < 1e-9,
            "{b:?}"
        );
        // A hexagon of apothem 1 along x has its corners 2 / sqrt 3 out along z.
        let half_width = 2.0 / 3f64.sqrt();
        assert!((b.max.z - half_width).abs() < 1e-9, "{b:?}");
        // Without its floor it is open downwards only.
        let open = polytope_extent(&pyramid()[..6], Aabb::INFINITE);
        assert!(
            open.min.y == f64::NEG_INFINITY && open.min.x == f64::NEG_INFINITY,
            "{open:?}"
        );
        assert!((open.max.y - 2.0).abs() < 1e-9, "{open:?}");
    }

    /// Random polytopes, some with nearly parallel planes (a turn by a right angle leaves
    /// a rounding error off the axis) and some unbounded: every point found inside all
    /// the half-spaces and a box lies in the extent.
    #[test]
    fn every_point_inside_lies_in_the_extent() {
        let mut rng = rand_pcg::Pcg64::seed_from_u64(7);
        let unit = |rng: &mut rand_pcg::Pcg64| {
            DVec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
        };
        for case in 0..300 {
            let count = 3 + case % 8;
            let centre = unit(&mut rng) * 10.0;
            let mut planes: Vec<HalfSpace> = (0..count)
                .map(|_| {
                    let n = unit(&mut rng);
                    HalfSpace::new(n, n.dot(centre) + 1.0)
                })
                .collect();
            if case % 3 == 0 {
                // A copy of the first turned by a hair.
                let h = planes[0];
                let n = h.normal + DVec3::new(1e-17, -3e-12, 2e-15);
                planes.push(HalfSpace::new(n, h.distance + 1e-13));
            }
            let within = if case % 2 == 0 {
                Aabb::INFINITE
            } else {
                Aabb::new(centre - 3.0, centre + 3.0)
            };
            let extent = polytope_extent(&planes, within);
            for _ in 0..2000 {
                let p = centre + unit(&mut rng) * 4.0;
                let inside = planes.iter().all(|h| h.normal.dot(p) <= h.distance)
                    && p.cmpge(within.min).all()
                    && p.cmple(within.max).all();
                let held = p.cmpge(extent.min).all() && p.cmple(extent.max).all();
                assert!(!inside || held, "case {case}: {p} outside {extent:?}");
            }
        }
    }
}
