//! The render-ready shapes: one enum, intersected in the shape's own space.

use glam::DVec3;

use super::{Aabb, Ray};

/// A closed set of shapes. Transformed instances keep their shape here in object space and
/// their transform beside them in [`super::Primitive`]; spheres and boxes that are only
/// translated and uniformly scaled are baked into world space when the scene is built.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShapeKind {
    Sphere { center: DVec3, radius: f64 },
    /// Points with `normal . p = distance`.
    Plane { normal: DVec3, distance: f64 },
    Box { min: DVec3, max: DVec3 },
}

impl ShapeKind {
    /// Object-space bounds; `None` for unbounded shapes.
    pub fn bounds(&self) -> Option<Aabb> {
        match *self {
            ShapeKind::Sphere { center, radius } => Some(Aabb::new(
                center - DVec3::splat(radius),
                center + DVec3::splat(radius),
            )),
            ShapeKind::Plane { .. } => None,
            ShapeKind::Box { min, max } => Some(Aabb::new(min, max)),
        }
    }

    /// Nearest hit distance in (0, t_max), in units of the ray's direction (which need not
    /// be normalised, so the same `t` holds in object and world space).
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        match *self {
            ShapeKind::Sphere { center, radius } => {
                let [t0, t1] = sphere_roots(ray, center, radius)?;
                if t0 > 0.0 && t0 < t_max {
                    Some(t0)
                } else if t1 > 0.0 && t1 < t_max {
                    Some(t1)
                } else {
                    None
                }
            }
            ShapeKind::Plane { normal, distance } => {
                let denom = normal.dot(ray.direction);
                if denom == 0.0 {
                    return None;
                }
                let t = (distance - normal.dot(ray.origin)) / denom;
                (t > 0.0 && t < t_max).then_some(t)
            }
            ShapeKind::Box { min, max } => {
                let inv = ray.direction.recip();
                let t1 = (min - ray.origin) * inv;
                let t2 = (max - ray.origin) * inv;
                let t_near = t1.min(t2).max_element();
                let t_far = t1.max(t2).min_element();
                if t_near > t_far {
                    return None;
                }
                if t_near > 0.0 && t_near < t_max {
                    Some(t_near)
                } else if t_far > 0.0 && t_far < t_max {
                    Some(t_far)
                } else {
                    None
                }
            }
        }
    }

    /// Outward geometric normal at a point on the surface, not normalised.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        match *self {
            ShapeKind::Sphere { center, .. } => p - center,
            ShapeKind::Plane { normal, .. } => normal,
            ShapeKind::Box { min, max } => {
                // The face whose plane the point is closest to, relative to the box size.
                let c = (min + max) * 0.5;
                let h = ((max - min) * 0.5).max(DVec3::splat(1e-300));
                let q = (p - c) / h;
                let a = q.abs();
                if a.x >= a.y && a.x >= a.z {
                    DVec3::new(q.x.signum(), 0.0, 0.0)
                } else if a.y >= a.z {
                    DVec3::new(0.0, q.y.signum(), 0.0)
                } else {
                    DVec3::new(0.0, 0.0, q.z.signum())
                }
            }
        }
    }

    /// Whether a point is inside the solid (POV-Ray's notion, used by CSG and interiors).
    pub fn inside(&self, p: DVec3) -> bool {
        match *self {
            ShapeKind::Sphere { center, radius } => (p - center).length_squared() < radius * radius,
            ShapeKind::Plane { normal, distance } => normal.dot(p) < distance,
            ShapeKind::Box { min, max } => p.cmpgt(min).all() && p.cmplt(max).all(),
        }
    }
}

/// Both roots of the ray-sphere quadratic, ordered, computed without catastrophic
/// cancellation: the discriminant from the perpendicular distance to the centre, and the
/// second root from the product of roots (q = -(b + sign(b) sqrt(disc)), t0 = q/a, t1 = c/q).
#[inline]
fn sphere_roots(ray: &Ray, center: DVec3, radius: f64) -> Option<[f64; 2]> {
    let d = ray.direction;
    let oc = ray.origin - center;
    let a = d.dot(d);
    let b = oc.dot(d); // half of the usual b
    let c = oc.dot(oc) - radius * radius;
    let perp = oc - d * (b / a);
    let disc = a * (radius * radius - perp.dot(perp));
    if disc < 0.0 || a == 0.0 {
        return None;
    }
    let q = -(b + b.signum() * disc.sqrt());
    if q == 0.0 {
        // Origin on the sphere and ray tangent; both roots are 0.
        return Some([0.0, 0.0]);
    }
    let (t0, t1) = (q / a, c / q);
    Some(if t0 <= t1 { [t0, t1] } else { [t1, t0] })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere(c: DVec3, r: f64) -> ShapeKind {
        ShapeKind::Sphere {
            center: c,
            radius: r,
        }
    }

    #[test]
    fn sphere_hit_from_outside_and_inside() {
        let s = sphere(DVec3::new(0.0, 0.0, 5.0), 1.0);
        let t = s.intersect(&Ray::new(DVec3::ZERO, DVec3::Z), f64::INFINITY);
        assert_eq!(t, Some(4.0));
        let t = s.intersect(&Ray::new(DVec3::new(0.0, 0.0, 5.0), DVec3::Z), f64::INFINITY);
        assert_eq!(t, Some(1.0));
        assert_eq!(s.intersect(&Ray::new(DVec3::ZERO, -DVec3::Z), f64::INFINITY), None);
        assert_eq!(s.intersect(&Ray::new(DVec3::ZERO, DVec3::Z), 3.9), None);
    }

    #[test]
    fn tangent_rays_hit_or_miss_correctly() {
        let s = sphere(DVec3::new(0.0, 0.0, 10.0), 1.0);
        for k in 1..=7 {
            let e = 10f64.powi(-k);
            let inside = Ray::new(DVec3::new(1.0 - e, 0.0, 0.0), DVec3::Z);
            let outside = Ray::new(DVec3::new(1.0 + e, 0.0, 0.0), DVec3::Z);
            assert!(s.intersect(&inside, f64::INFINITY).is_some(), "k={k}");
            assert!(s.intersect(&outside, f64::INFINITY).is_none(), "k={k}");
        }
    }

    #[test]
    fn far_and_huge_spheres_hit_on_the_surface() {
        for (dist, r) in [(1e4, 1.0), (1e7, 1.0), (1e6, 1e4), (10.0, 1e-3)] {
            let c = DVec3::new(0.3 * r, 0.2 * r, dist);
            let s = sphere(c, r);
            let ray = Ray::new(DVec3::ZERO, DVec3::Z);
            let t = s.intersect(&ray, f64::INFINITY).expect("hit");
            let err = ((ray.at(t) - c).length() - r).abs();
            assert!(err <= 8.0 * f64::EPSILON * dist.max(r), "{dist} {r}: {err}");
        }
    }

    #[test]
    fn box_and_plane() {
        let b = ShapeKind::Box {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        };
        let ray = Ray::new(DVec3::new(0.5, 0.0, -5.0), DVec3::Z);
        let t = b.intersect(&ray, f64::INFINITY).unwrap();
        assert_eq!(t, 4.0);
        assert_eq!(b.normal(ray.at(t)), DVec3::new(0.0, 0.0, -1.0));
        assert!(b.inside(DVec3::ZERO) && !b.inside(DVec3::splat(2.0)));
        let p = ShapeKind::Plane {
            normal: DVec3::Y,
            distance: -1.0,
        };
        let t = p.intersect(&Ray::new(DVec3::ZERO, DVec3::new(0.0, -1.0, 1.0)), f64::INFINITY);
        assert_eq!(t, Some(1.0));
        assert!(p.inside(DVec3::new(0.0, -2.0, 0.0)));
    }
}
