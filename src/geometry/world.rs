//! The render-ready geometry: primitives with baked transforms, a BVH over the bounded
//! ones, and the unbounded ones (planes) kept aside.

use glam::DVec3;

use super::{Aabb, Bvh, Ray, ShapeKind, Transform};

/// Per-primitive visibility flags, tested as a mask so each kind of ray can skip some.
pub mod flags {
    pub const NO_SHADOW: u8 = 1;
    pub const NO_IMAGE: u8 = 2;
    pub const NO_REFLECTION: u8 = 4;
}

const NO_TRANSFORM: u32 = u32::MAX;

#[derive(Clone, Copy, Debug)]
pub struct Primitive {
    pub shape: ShapeKind,
    /// Index into `World::transforms`, or `NO_TRANSFORM` when the shape is in world space.
    transform: u32,
    pub material: u32,
    pub flags: u8,
}

#[derive(Clone, Copy, Debug)]
pub struct Hit {
    pub t: f64,
    pub primitive: u32,
}

/// Where a ray met a surface, in world space.
#[derive(Clone, Copy, Debug)]
pub struct SurfacePoint {
    pub point: DVec3,
    /// Outward geometric normal, unit length.
    pub normal: DVec3,
    pub material: u32,
}

#[derive(Clone, Debug, Default)]
pub struct World {
    primitives: Vec<Primitive>,
    transforms: Vec<Transform>,
    bvh: Bvh,
    unbounded: Vec<u32>,
}

/// Collects primitives, then builds the BVH once.
#[derive(Default)]
pub struct WorldBuilder {
    primitives: Vec<Primitive>,
    transforms: Vec<Transform>,
}

impl WorldBuilder {
    /// Adds a shape placed by `transform`; simple placements are baked into the shape.
    pub fn add(&mut self, shape: ShapeKind, transform: &Transform, material: u32, flags: u8) {
        let (shape, index) = match bake(shape, transform) {
            Some(baked) => (baked, NO_TRANSFORM),
            None => {
                self.transforms.push(*transform);
                (shape, (self.transforms.len() - 1) as u32)
            }
        };
        self.primitives.push(Primitive {
            shape,
            transform: index,
            material,
            flags,
        });
    }

    pub fn build(self) -> World {
        let mut bounded = Vec::new();
        let mut bounds = Vec::new();
        let mut unbounded = Vec::new();
        for (i, p) in self.primitives.iter().enumerate() {
            let b = p.shape.bounds().map(|b| match p.transform {
                NO_TRANSFORM => b,
                t => b.transformed(&self.transforms[t as usize]),
            });
            match b {
                Some(b) if b.is_finite() && !b.is_empty() => {
                    bounded.push(i as u32);
                    bounds.push(b);
                }
                _ => unbounded.push(i as u32),
            }
        }
        let mut bvh = Bvh::build(&bounds);
        for item in &mut bvh.items {
            *item = bounded[*item as usize];
        }
        World {
            primitives: self.primitives,
            transforms: self.transforms,
            bvh,
            unbounded,
        }
    }
}

/// Shapes whose transform keeps them the same kind in world space (a sphere under
/// translation and uniform scale, a box under translation and axis scales, a plane under any
/// map) are rewritten in world space, which saves a transform per ray test.
fn bake(shape: ShapeKind, t: &Transform) -> Option<ShapeKind> {
    if t.is_identity() {
        return Some(shape);
    }
    let m = t.forward.matrix3;
    let off_diagonal = m.x_axis.y.abs()
        + m.x_axis.z.abs()
        + m.y_axis.x.abs()
        + m.y_axis.z.abs()
        + m.z_axis.x.abs()
        + m.z_axis.y.abs();
    let diag = DVec3::new(m.x_axis.x, m.y_axis.y, m.z_axis.z);
    match shape {
        ShapeKind::Sphere { center, radius } => {
            let uniform = off_diagonal == 0.0 && diag.x == diag.y && diag.y == diag.z;
            uniform.then(|| ShapeKind::Sphere {
                center: t.point(center),
                radius: radius * diag.x.abs(),
            })
        }
        ShapeKind::Box { min, max } => (off_diagonal == 0.0).then(|| ShapeKind::Box {
            min: t.point(min).min(t.point(max)),
            max: t.point(min).max(t.point(max)),
        }),
        ShapeKind::Plane { normal, distance } => {
            let n = t.normal(normal);
            let len = n.length();
            let p = t.point(normal * (distance / normal.length_squared()));
            let n = n / len;
            Some(ShapeKind::Plane {
                normal: n,
                distance: n.dot(p),
            })
        }
    }
}

impl World {
    pub fn primitive_count(&self) -> usize {
        self.primitives.len()
    }

    #[inline]
    fn primitive_hit(&self, p: &Primitive, ray: &Ray, t_max: f64) -> Option<f64> {
        if p.transform == NO_TRANSFORM {
            p.shape.intersect(ray, t_max)
        } else {
            let t = &self.transforms[p.transform as usize];
            let local = Ray::new(t.inverse_point(ray.origin), t.inverse_vector(ray.direction));
            p.shape.intersect(&local, t_max)
        }
    }

    /// The nearest hit in (0, t_max), ignoring primitives with any of the `skip` flags.
    pub fn intersect(&self, ray: &Ray, t_max: f64, skip: u8) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut t_best = t_max;
        for &i in &self.unbounded {
            let p = &self.primitives[i as usize];
            if p.flags & skip == 0 {
                if let Some(t) = self.primitive_hit(p, ray, t_best) {
                    t_best = t;
                    best = Some(Hit { t, primitive: i });
                }
            }
        }
        self.bvh.traverse(ray, t_best, |i, t_cur| {
            let p = &self.primitives[i as usize];
            if p.flags & skip == 0 {
                if let Some(t) = self.primitive_hit(p, ray, t_cur) {
                    best = Some(Hit { t, primitive: i });
                    return Some(t);
                }
            }
            Some(t_cur)
        });
        best
    }

    /// Whether anything that casts shadows lies on the ray within (0, t_max); stops at the
    /// first hit.
    pub fn occluded(&self, ray: &Ray, t_max: f64) -> bool {
        let skip = flags::NO_SHADOW;
        for &i in &self.unbounded {
            let p = &self.primitives[i as usize];
            if p.flags & skip == 0 && self.primitive_hit(p, ray, t_max).is_some() {
                return true;
            }
        }
        let mut hit = false;
        self.bvh.traverse(ray, t_max, |i, t_cur| {
            let p = &self.primitives[i as usize];
            if p.flags & skip == 0 && self.primitive_hit(p, ray, t_cur).is_some() {
                hit = true;
                return None;
            }
            Some(t_cur)
        });
        hit
    }

    pub fn surface(&self, ray: &Ray, hit: &Hit) -> SurfacePoint {
        let p = &self.primitives[hit.primitive as usize];
        let point = ray.at(hit.t);
        let normal = if p.transform == NO_TRANSFORM {
            p.shape.normal(point)
        } else {
            let t = &self.transforms[p.transform as usize];
            t.normal(p.shape.normal(t.inverse_point(point)))
        };
        SurfacePoint {
            point,
            normal: normal.normalize_or(DVec3::Y),
            material: p.material,
        }
    }

    pub fn bounds(&self) -> Aabb {
        self.bvh.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds)
    }
}
