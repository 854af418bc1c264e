use glam::DVec3;

use super::Ray;

/// An axis-aligned box; `EMPTY` has min > max so that growing it by a point gives that point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: DVec3,
    pub max: DVec3,
}

impl Default for Aabb {
    fn default() -> Aabb {
        Aabb::EMPTY
    }
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    /// Everywhere: the extent of a solid unbounded every way.
    pub const INFINITE: Aabb = Aabb {
        min: DVec3::splat(f64::NEG_INFINITY),
        max: DVec3::splat(f64::INFINITY),
    };

    pub fn new(a: DVec3, b: DVec3) -> Aabb {
        Aabb {
            min: a.min(b),
            max: a.max(b),
        }
    }

    pub fn union(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }

    pub fn grow(&self, p: DVec3) -> Aabb {
        Aabb {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y || self.min.z > self.max.z
    }

    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    pub fn centre(&self) -> DVec3 {
        (self.min + self.max) * 0.5
    }

    pub fn surface_area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.max - self.min;
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// The box of this box's eight corners under an affine map.
    pub fn transformed(&self, t: &super::Transform) -> Aabb {
        let mut out = Aabb::EMPTY;
        for i in 0..8 {
            let c = DVec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            );
            out = out.grow(t.point(c));
        }
        out
    }

    pub fn intersection(&self, o: &Aabb) -> Aabb {
        Aabb {
            min: self.min.max(o.min),
            max: self.max.min(o.max),
        }
    }

    /// The box as a bound: `None` where a side is open (infinite) and the box not empty.
    pub fn bounded(self) -> Option<Aabb> {
        (self.is_finite() || self.is_empty()).then_some(self)
    }

    /// [`Aabb::transformed`] for a box that may have infinite sides: those stay infinite
    /// under a transform that takes each axis exactly onto an axis (scales, translations,
    /// swaps of axes; a turn by a right angle leaves a rounding error off the axis, which
    /// an infinite side would spread everywhere); under any other the box is everywhere.
    pub fn transformed_extent(&self, t: &super::Transform) -> Aabb {
        if self.is_finite() || self.is_empty() {
            return self.transformed(t);
        }
        let (m, shift) = (t.forward.matrix3, t.forward.translation);
        let mut out = Aabb::INFINITE;
        for axis in 0..3 {
            let column = m.col(axis);
            let onto: Vec<usize> = (0..3).filter(|&j| column[j] != 0.0).collect();
            let [j] = onto[..] else {
                return Aabb::INFINITE;
            };
            let (a, b) = (self.min[axis] * column[j], self.max[axis] * column[j]);
            out.min[j] = a.min(b) + shift[j];
            out.max[j] = a.max(b) + shift[j];
        }
        out
    }

    /// Slab test: the entry and exit distances, if the ray meets the box within (0, t_max).
    /// `inv_dir` is 1/direction per component (infinities are fine).
    #[inline]
    pub fn hit(&self, ray: &Ray, inv_dir: DVec3, t_max: f64) -> Option<f64> {
        let t1 = (self.min - ray.origin) * inv_dir;
        let t2 = (self.max - ray.origin) * inv_dir;
        // min/max with NaN (0 * inf) pick the other operand, which keeps the test conservative.
        let t_near = t1.min(t2).max_element().max(0.0);
        let t_far = t1.max(t2).min_element().min(t_max);
        // A little slack: rounding must never make a ray miss the box of what it hits.
        if t_near <= t_far * (1.0 + 4.0 * f64::EPSILON) {
            Some(t_near)
        } else {
            None
        }
    }
}
