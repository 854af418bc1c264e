//! Shaft culling (Haines and Wallace, "Shaft Culling for Efficient Ray-Traced Radiosity",
//! 1991): the shadow rays from one point towards an area light's points lie in the convex
//! hull of that point and a quadrilateral holding the light's points, so only objects whose
//! boxes meet the hull can stop them. One walk of the tree per shading point then stands
//! for a walk per shadow ray, and where no box meets the hull every ray reaches the light.

use glam::DVec3;

use super::Aabb;

/// The hull's slanted faces: four sides through the apex and the base.
const FACES: usize = 5;

/// The convex hull of an apex and a quadrilateral, as half-spaces that each hold all of it:
/// its box and its faces. A box outside one of them misses the hull; a box inside all of
/// them may still miss it (at an edge), which costs a test, never a shadow.
#[derive(Clone, Copy, Debug)]
pub struct Shaft {
    /// The hull's box, grown by the margin.
    bounds: Aabb,
    /// Normals `n` and offsets `d` of the faces: `n . x <= d` holds the hull.
    normals: [DVec3; FACES],
    offsets: [f64; FACES],
    faces: usize,
    /// The apex and the base's corners.
    points: [DVec3; 5],
    margin: f64,
}

impl Shaft {
    /// The hull of `apex` and `base` (the corners of a parallelogram in order around it; a
    /// flat or degenerate one is fine, a face without a direction is left out).
    ///
    /// The margin, 1e-13 of the largest coordinate, covers the roundings of the shadow
    /// rays' directions and of the light's points (a few units of 1e-16 of the same
    /// magnitudes) a thousand times over, and stays below a shading point's offset from
    /// its surface (1e-11 of its coordinates, [`super::offset_scale`]), so that the
    /// surface a point lies on is left out where it faces the light.
    #[inline]
    pub fn new(apex: DVec3, base: [DVec3; 4]) -> Shaft {
        let points = [apex, base[0], base[1], base[2], base[3]];
        let scale = points
            .iter()
            .map(|p| p.abs().max_element())
            .fold(0.0, f64::max);
        let margin = scale * 1e-13;
        let bounds = points.iter().fold(Aabb::EMPTY, |b, &p| b.grow(p));
        let mut shaft = Shaft {
            bounds: Aabb::new(bounds.min - margin, bounds.max + margin),
            normals: [DVec3::ZERO; FACES],
            offsets: [0.0; FACES],
            faces: 0,
            points,
            margin,
        };
        let centroid = points.iter().sum::<DVec3>() / 5.0;
        for k in 0..4 {
            let (a, b) = (base[k] - apex, base[(k + 1) % 4] - apex);
            shaft.add_face(a.cross(b), apex, centroid, margin);
        }
        let across = (base[1] - base[0]).cross(base[3] - base[0]);
        shaft.add_face(across, base[0], centroid, margin);
        shaft
    }

    /// The face through `on` with normal `n` (of any length), turned away from the hull's
    /// `inner` point. Its offset is the farthest of the hull's points along it, so it holds
    /// them whichever way rounding turned it, plus the margin times |n|'s 1-norm (at least
    /// its length: no square root).
    fn add_face(&mut self, n: DVec3, on: DVec3, inner: DVec3, margin: f64) {
        let size = n.abs().element_sum();
        if !(size > 0.0 && size.is_finite()) {
            return;
        }
        let n = if n.dot(inner - on) > 0.0 { -n } else { n };
        let farthest = self
            .points
            .iter()
            .map(|&p| n.dot(p))
            .fold(f64::MIN, f64::max);
        self.normals[self.faces] = n;
        self.offsets[self.faces] = farthest + margin * size;
        self.faces += 1;
    }

    /// Whether the hull lies wholly on one side of the plane `normal . x = distance`, clear
    /// of it by more than the margin: then no ray inside the hull meets the plane. (A
    /// plane's box is its half-space, grown a little, which a point on the plane's surface
    /// always meets.)
    pub fn beside(&self, normal: DVec3, distance: f64) -> bool {
        let clear = self.margin * normal.abs().element_sum() + distance.abs() * 1e-13;
        let sides = self.points.map(|p| normal.dot(p) - distance);
        sides.iter().all(|&s| s > clear) || sides.iter().all(|&s| s < -clear)
    }

    /// Whether the box lies wholly outside the hull's box or one of its faces. Infinite
    /// sides are fine; a NaN (an infinite side times a zero component) decides nothing.
    pub fn misses(&self, b: &Aabb) -> bool {
        let s = &self.bounds;
        if (0..3).any(|a| b.min[a] > s.max[a] || b.max[a] < s.min[a]) {
            return true;
        }
        (0..self.faces).any(|f| {
            let n = self.normals[f];
            // The box's least value along n (each axis at the bound n's sign picks), and a
            // bound on its rounding, which a box far larger than the hull needs.
            let terms = DVec3::from_array(std::array::from_fn(|a| {
                n[a] * if n[a] >= 0.0 { b.min[a] } else { b.max[a] }
            }));
            terms.element_sum() > self.offsets[f] + 4.0 * f64::EPSILON * terms.abs().element_sum()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shaft() -> Shaft {
        let apex = DVec3::new(0.0, 0.0, 0.0);
        let base = [
            DVec3::new(-1.0, 4.0, -1.0),
            DVec3::new(1.0, 4.0, -1.0),
            DVec3::new(1.0, 4.0, 1.0),
            DVec3::new(-1.0, 4.0, 1.0),
        ];
        Shaft::new(apex, base)
    }

    fn cube(centre: DVec3, half: f64) -> Aabb {
        Aabb::new(centre - half, centre + half)
    }

    /// Boxes on the segments from the apex to points of the base are never missed; boxes
    /// beside the pyramid, beyond its base or behind its apex are.
    #[test]
    fn a_shaft_keeps_what_its_rays_meet_and_drops_what_lies_beside_it() {
        let s = shaft();
        let mut uniform = crate::geometry::uniform_stream(0x2545_F491_4F6C_DD1Du64);
        for _ in 0..10_000 {
            let (u, v, t) = (uniform() * 2.0 - 1.0, uniform() * 2.0 - 1.0, uniform());
            let on_ray = DVec3::new(u, 4.0, v) * t;
            assert!(!s.misses(&cube(on_ray, 1e-9)), "{on_ray}");
            // And a box of no size at the point itself.
            assert!(!s.misses(&Aabb::new(on_ray, on_ray)), "{on_ray}");
        }
        // Beside a side face, half-way up: the side x = y / 4 lies at x = 0.5 there.
        assert!(s.misses(&cube(DVec3::new(0.6, 2.0, 0.0), 0.05)));
        assert!(!s.misses(&cube(DVec3::new(0.6, 2.0, 0.0), 0.15)));
        // Beyond the base, behind the apex, and an unbounded floor below the apex.
        assert!(s.misses(&cube(DVec3::new(0.0, 4.2, 0.0), 0.1)));
        assert!(s.misses(&cube(DVec3::new(0.0, -0.2, 0.0), 0.1)));
        let floor = Aabb {
            min: DVec3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY),
            max: DVec3::new(f64::INFINITY, -1e-12, f64::INFINITY),
        };
        assert!(s.misses(&floor));
        let through = Aabb {
            max: DVec3::new(f64::INFINITY, 0.0, f64::INFINITY),
            ..floor
        };
        assert!(!s.misses(&through));
    }

    /// A floor through the apex's foot: a shaft whose apex lies above it by more than the
    /// margin is beside it, one whose apex lies on it is not, nor one that reaches through.
    #[test]
    fn a_plane_is_beside_a_shaft_only_with_the_whole_hull_on_one_side() {
        let base = shaft().points;
        let up = DVec3::Y;
        let lifted = |y: f64| {
            Shaft::new(
                DVec3::new(0.3, y, 0.2),
                [base[1], base[2], base[3], base[4]],
            )
        };
        assert!(lifted(1e-11).beside(up, 0.0));
        assert!(!lifted(0.0).beside(up, 0.0));
        assert!(!lifted(-0.5).beside(up, 0.0));
        assert!(lifted(1e-11).beside(-up, 0.0));
        assert!(lifted(1.0).beside(up, 0.5));
        assert!(!lifted(1.0).beside(up, 4.0));
        assert!(lifted(1.0).beside(up, 4.5));
    }

    /// A light that is a line (its quadrilateral flat) or a point leaves a flat hull or a
    /// segment: the faces without a direction are left out, and what the segment meets is
    /// kept.
    #[test]
    fn degenerate_bases_keep_a_conservative_hull() {
        let apex = DVec3::new(0.0, 0.0, 0.0);
        let p = DVec3::new(0.0, 4.0, 0.0);
        let s = Shaft::new(apex, [p; 4]);
        assert!(!s.misses(&cube(DVec3::new(0.0, 2.0, 0.0), 1e-9)));
        assert!(s.misses(&cube(DVec3::new(0.1, 2.0, 0.0), 0.05)));
        let (a, b) = (DVec3::new(-1.0, 4.0, 0.0), DVec3::new(1.0, 4.0, 0.0));
        let line = Shaft::new(apex, [a, b, b, a]);
        assert!(!line.misses(&cube(DVec3::new(0.4, 2.0, 0.0), 1e-9)));
        assert!(line.misses(&cube(DVec3::new(0.0, 2.0, 0.3), 0.1)));
    }
}
