//! Trees over a few items are walked as a list: each item's box in turn, in double
//! precision. A walk's set-up (the ray in single precision, rounded outward, and the
//! node tests' values broadcast to four lanes) cost a small scene's camera ray about 240
//! instructions before its first node (checker, callgrind), more than testing its two
//! boxes.

use super::{Bvh, NodeBox};
use crate::geometry::{Aabb, Ray};

/// Most items a tree walks as a list.
pub(super) const FEW: usize = 8;

/// Slack on a box's far distance: the test's roundings (the reciprocal, the difference,
/// the product) each err by at most 2^-53, so a far distance scaled by 1 + 2 gamma(3)
/// (pbrt's bound) is never nearer than the exact one.
const SLACK: f64 = 1.0 + 2.0 * (3.0 * f64::EPSILON / 2.0) / (1.0 - 3.0 * f64::EPSILON / 2.0);

/// A box as the list tests it: per axis, its minimum and maximum.
pub(super) type ListBox = [[f64; 2]; 3];

/// The boxes of the positions in leaf order, for a tree of at most [`FEW`] items (else
/// none). They are the nodes' boxes (single precision, rounded outward) in double
/// precision, so the list meets every box the tree's walk meets.
pub(super) fn boxes(items: &[u32], bounds_of: impl Fn(usize) -> Aabb) -> Vec<ListBox> {
    if items.len() > FEW {
        return Vec::new();
    }
    items
        .iter()
        .map(|&i| {
            let b = NodeBox::enclosing(&bounds_of(i as usize)).aabb();
            [0, 1, 2].map(|axis| [b.min[axis], b.max[axis]])
        })
        .collect()
}

/// A list box as a box.
pub(super) fn own_box(&[x, y, z]: &ListBox) -> Aabb {
    Aabb {
        min: glam::DVec3::new(x[0], y[0], z[0]),
        max: glam::DVec3::new(x[1], y[1], z[1]),
    }
}

/// A ray as the list's box tests need it.
struct ListRay {
    origin: [f64; 3],
    inv: [f64; 3],
    /// Per axis: which bound holds the near plane (1, the maxima, when the ray runs
    /// toward -axis).
    near: [usize; 3],
}

impl ListRay {
    #[inline(always)]
    fn new(ray: &Ray) -> ListRay {
        let inv = ray.direction.to_array().map(|d| 1.0 / d);
        ListRay {
            origin: ray.origin.to_array(),
            inv,
            near: inv.map(|i| usize::from(i < 0.0)),
        }
    }

    /// Whether the ray meets the box within [0, t_max]. A NaN (0 x infinity, a ray in a
    /// slab's plane) fails the comparisons and leaves the interval as it was, which keeps
    /// the test conservative.
    #[inline(always)]
    fn meets(&self, b: &ListBox, t_max: f64) -> bool {
        let (mut t0, mut t1) = (0.0, t_max);
        for (axis, bounds) in b.iter().enumerate() {
            let n = self.near[axis];
            let near = (bounds[n] - self.origin[axis]) * self.inv[axis];
            let far = (bounds[1 - n] - self.origin[axis]) * self.inv[axis];
            if near > t0 {
                t0 = near;
            }
            if far < t1 {
                t1 = far;
            }
        }
        t0 <= t1 * SLACK
    }
}

impl Bvh {
    /// [`Bvh::traverse`] over a tree of few items: every item whose box the ray meets,
    /// in leaf order.
    #[inline(always)]
    pub(super) fn traverse_few(
        &self,
        ray: &Ray,
        mut t_max: f64,
        mut visit: impl FnMut(u32, f64) -> Option<f64>,
    ) {
        let r = ListRay::new(ray);
        for (k, b) in self.few.iter().enumerate() {
            if r.meets(b, t_max) {
                match visit(self.item(k), t_max) {
                    Some(t) => t_max = t,
                    None => return,
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;

    /// Rays aimed at a point inside or on one of a few random boxes visit that box; the
    /// tree is walked as a list. Corners on a grid of eighths (exact in single precision,
    /// so flat boxes stay flat) and a third of the rays in the plane of a box's face,
    /// parallel to it (0 x infinity in the test).
    #[test]
    fn the_list_visits_every_box_a_ray_enters() {
        let mut uniform = crate::geometry::uniform_stream(0x9E37_79B9_7F4A_7C15u64);
        // Eighths in [0, scale).
        let mut grid = move |scale: f64| (uniform() * scale * 8.0).floor() / 8.0;
        let mut corner = |scale: f64| DVec3::new(grid(scale), grid(scale), grid(scale));
        for n in 1..=FEW {
            for k in 0..500 {
                let boxes: Vec<Aabb> = (0..n)
                    .map(|_| {
                        let a = corner(4.0) - 2.0;
                        Aabb::new(a, a + corner(1.0))
                    })
                    .collect();
                let bvh = Bvh::build(&boxes);
                assert_eq!(bvh.few.len(), n);
                let target = k % n;
                let b = &boxes[target];
                let mut inside = b.min + (b.max - b.min) * corner(1.0);
                let mut origin = corner(10.0) - 5.0;
                if k % 3 == 0 {
                    let axis = k / 3 % 3;
                    (origin[axis], inside[axis]) = (b.min[axis], b.min[axis]);
                }
                let to = inside - origin;
                if to.length() == 0.0 {
                    continue;
                }
                let mut seen = false;
                let ray = Ray::new(origin, to / to.length());
                bvh.traverse(&ray, to.length() * 1.5, |i, t| {
                    seen |= i as usize == target;
                    Some(t)
                });
                assert!(
                    seen,
                    "box {target} of {n} missed by a ray from {origin} to {inside}"
                );
            }
        }
    }

    /// Boxes entered beyond the walk's reach, once a hit shrinks it, are passed over.
    #[test]
    fn the_list_passes_over_boxes_beyond_the_nearest_hit() {
        let boxes: Vec<Aabb> = (0..4)
            .map(|i| {
                let x = f64::from(i) * 2.0;
                Aabb::new(DVec3::new(x, -0.5, -0.5), DVec3::new(x + 1.0, 0.5, 0.5))
            })
            .collect();
        let bvh = Bvh::build(&boxes);
        let mut seen = Vec::new();
        let ray = Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X);
        bvh.traverse(&ray, f64::INFINITY, |i, _| {
            seen.push(i);
            Some(0.5)
        });
        assert_eq!(seen.len(), 1, "{seen:?}");
        let mut all = Vec::new();
        bvh.traverse(&ray, 5.5, |i, t| {
            all.push(i);
            Some(t)
        });
        all.sort_unstable();
        assert_eq!(all, vec![0, 1, 2]);
    }
}
