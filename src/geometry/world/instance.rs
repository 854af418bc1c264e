//! Instances: one prototype's geometry (its primitives, CSG nodes, tables and BVH) shared by
//! every placement of it. A forest of 10^4 trees of 10^3 parts holds 10^3 primitives and
//! 10^4 instances, not 10^7 primitives.
//!
//! A ray meets an instance in the prototype's space: its direction is mapped but not
//! normalised, so distances along it are the world's. The hit keeps which instance it came
//! through, and the surface is mapped back to world space from there.

use std::sync::Arc;

use glam::DVec3;

use super::{
    Aabb, CsgOp, Hit, MaterialBlend, NO_INSTANCE, Ray, SurfacePoint, TexturePoint, World, flags,
};
use crate::geometry::Transform;

#[derive(Clone, Debug)]
pub struct Instance {
    /// The prototype, with no instances of its own.
    world: Arc<World>,
    /// Prototype space to world space.
    transform: Transform,
    /// Where this placement's materials start: the prototype's material m is
    /// `materials + m` in the scene's table.
    materials: u32,
}

impl Instance {
    pub(super) fn new(world: Arc<World>, transform: Transform, materials: u32) -> Instance {
        debug_assert!(world.instances.is_empty(), "prototypes hold no instances");
        Instance {
            world,
            transform,
            materials,
        }
    }

    /// The prototype's world, shared with the other placements.
    pub fn prototype(&self) -> &Arc<World> {
        &self.world
    }

    fn local_ray(&self, ray: &Ray) -> Ray {
        self.transform.inverse_ray(ray)
    }

    /// The hit as the prototype knows it.
    fn local_hit(hit: &Hit) -> Hit {
        Hit {
            instance: NO_INSTANCE,
            ..*hit
        }
    }

    pub(super) fn bounds(&self) -> Option<Aabb> {
        if !self.world.unbounded.is_empty() {
            return None;
        }
        Some(self.world.bounds().transformed(&self.transform))
    }

    pub(super) fn holds_bound(&self) -> bool {
        self.world.csg.iter().any(|n| n.op == CsgOp::Bound)
    }

    pub(super) fn holds(&self, p: DVec3) -> bool {
        self.world.holds(self.transform.inverse_point(p))
    }

    pub(super) fn first_material(&self) -> Option<u32> {
        Some(self.materials + self.world.top_material()?)
    }

    /// The materials of the prototype's top-level items that hold `p`.
    pub(super) fn containing(&self, p: DVec3) -> impl Iterator<Item = u32> + '_ {
        let local = self.transform.inverse_point(p);
        self.world.containing(local).map(|m| m + self.materials)
    }

    pub(super) fn hit(&self, index: u32, ray: &Ray, t_max: f64, skip: u8) -> Option<Hit> {
        let hit = self.world.intersect(&self.local_ray(ray), t_max, skip)?;
        Some(Hit {
            instance: index,
            ..hit
        })
    }

    pub(super) fn blocks(&self, ray: &Ray, t_max: f64) -> bool {
        self.world.occluded(&self.local_ray(ray), t_max)
    }

    pub(super) fn for_each_hit(
        &self,
        index: u32,
        ray: &Ray,
        t_max: f64,
        skip: u8,
        f: &mut dyn FnMut(Hit),
    ) {
        self.world
            .crossings(&self.local_ray(ray), t_max, skip, &mut |hit| {
                f(Hit {
                    instance: index,
                    ..*hit
                });
                true
            });
    }

    pub(super) fn hit_material(&self, hit: &Hit) -> u32 {
        self.materials + self.world.hit_material(&Self::local_hit(hit))
    }

    pub(super) fn surface(&self, ray: &Ray, hit: &Hit) -> SurfacePoint {
        let local = self
            .world
            .surface(&self.local_ray(ray), &Self::local_hit(hit));
        let normal = self.transform.normal(local.normal).normalize_or(DVec3::Y);
        let mut shading_normal = self
            .transform
            .normal(local.shading_normal)
            .normalize_or(normal);
        if shading_normal.dot(normal) < 0.0 {
            shading_normal = -shading_normal;
        }
        let point = ray.at(hit.t);
        SurfacePoint {
            point,
            normal,
            shading_normal,
            material: self.materials + local.material,
            uv: self.uv(hit, local.uv, point),
            blend: local.blend.and_then(|b| self.blend(b)),
        }
    }

    pub(super) fn texture_point(&self, ray: &Ray, hit: &Hit) -> TexturePoint {
        let local = self
            .world
            .texture_point(&self.local_ray(ray), &Self::local_hit(hit));
        let point = ray.at(hit.t);
        TexturePoint {
            world: point,
            uv: self.uv(hit, local.uv, point),
            normal: DVec3::ZERO,
        }
    }

    /// The surface's own (u, v) where its material reads them, else the world x and y
    /// (the prototype gave its own space's).
    fn uv(&self, hit: &Hit, local: glam::DVec2, point: DVec3) -> glam::DVec2 {
        let own = self.world.primitives[hit.primitive as usize].flags & flags::UV != 0;
        if own { local } else { point.truncate() }
    }

    /// A mesh face's corner materials, numbered in the scene's table. A blob's blend reads
    /// the prototype's own tables, so the scene builds no prototype with a textured blob
    /// (it copies such an object instead); were one here, it would show its own material.
    fn blend(&self, blend: MaterialBlend) -> Option<MaterialBlend> {
        match blend {
            MaterialBlend::Corners { materials, weights } => Some(MaterialBlend::Corners {
                materials: materials.map(|m| m + self.materials),
                weights,
            }),
            MaterialBlend::Blob { .. } => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Item, WorldBuilder};
    use super::*;
    use crate::geometry::ShapeKind;

    /// The prototype's parts: (shape, its own placement, material, flags); a difference of
    /// the first two, the others alone.
    fn parts() -> Vec<(ShapeKind, Transform, u32, u8)> {
        let sphere = |x: f64, r: f64| ShapeKind::Sphere {
            center: DVec3::new(x, 0.5, 0.0),
            radius: r,
        };
        let squash = Transform::scale(DVec3::new(1.0, 0.4, 0.7)).expect("invertible");
        let tilt = Transform::rotate(DVec3::new(20.0, 35.0, 0.0));
        vec![
            (
                ShapeKind::Box {
                    min: DVec3::splat(-0.6),
                    max: DVec3::splat(0.6),
                },
                tilt,
                0,
                0,
            ),
            (sphere(0.5, 0.5), Transform::IDENTITY, 1, 0),
            (sphere(-1.5, 0.6), squash, 2, 0),
            (sphere(1.8, 0.4), tilt, 1, flags::NO_SHADOW),
        ]
    }

    /// The parts under `placement`, materials from `first` on, in `b`.
    fn add_parts(b: &mut WorldBuilder, placement: &Transform, first: u32) -> Vec<Item> {
        let items: Vec<Item> = parts()
            .into_iter()
            .map(|(shape, own, m, f)| b.primitive(shape, &own.then(placement), first + m, f))
            .collect();
        let d = b.csg(CsgOp::Difference, items[..2].to_vec(), false);
        vec![d, items[2], items[3]]
    }

    fn placements() -> Vec<Transform> {
        let scale = |v: DVec3| Transform::scale(v).expect("invertible");
        vec![
            Transform::translate(DVec3::new(3.0, 0.0, 1.0)),
            Transform::rotate(DVec3::new(0.0, 70.0, 10.0))
                .then(&Transform::translate(DVec3::new(-2.0, 1.0, 0.5))),
            scale(DVec3::new(1.5, 0.6, 1.0))
                .then(&Transform::translate(DVec3::new(0.0, -1.0, 3.0))),
            // A mirror: outward normals must stay outward.
            scale(DVec3::new(-1.0, 1.0, 1.0))
                .then(&Transform::translate(DVec3::new(0.5, 2.0, -2.0))),
        ]
    }

    const MATERIALS: u32 = 3;

    fn instanced() -> World {
        let mut p = WorldBuilder::default();
        for item in add_parts(&mut p, &Transform::IDENTITY, 0) {
            p.add_top(item);
        }
        let prototype = Arc::new(p.build());
        let mut b = WorldBuilder::default();
        for (k, placement) in placements().iter().enumerate() {
            let item = b.instance(prototype.clone(), *placement, k as u32 * MATERIALS);
            b.add_top(item);
        }
        let cut = b.instance(prototype, cut_placement(), CUT_MATERIAL);
        let slab = slab(&mut b);
        let item = b.csg(CsgOp::Difference, vec![slab, cut], false);
        b.add_top(item);
        b.build()
    }

    /// Where the prototype cuts a slab: a difference with an instance as its second child.
    fn cut_placement() -> Transform {
        Transform::rotate(DVec3::new(0.0, 0.0, 40.0))
            .then(&Transform::translate(DVec3::new(0.0, -3.0, -1.0)))
    }

    const CUT_MATERIAL: u32 = 100;

    fn slab(b: &mut WorldBuilder) -> Item {
        let shape = ShapeKind::Box {
            min: DVec3::new(-2.5, -3.2, -2.0),
            max: DVec3::new(2.5, -2.8, 1.0),
        };
        b.primitive(shape, &Transform::IDENTITY, 99, 0)
    }

    fn copied() -> World {
        let mut b = WorldBuilder::default();
        for (k, placement) in placements().iter().enumerate() {
            for item in add_parts(&mut b, placement, k as u32 * MATERIALS) {
                b.add_top(item);
            }
        }
        let parts = add_parts(&mut b, &cut_placement(), CUT_MATERIAL);
        let cut = b.csg(CsgOp::Union, parts, false);
        let slab = slab(&mut b);
        let item = b.csg(CsgOp::Difference, vec![slab, cut], false);
        b.add_top(item);
        b.build()
    }

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-7
    }

    /// Rays and points through four placements of a prototype (a CSG difference, a squashed
    /// sphere, a sphere that casts no shadow), one of them mirrored, and a fifth that cuts a
    /// slab (a CSG child): the instances answer as copies of the parts under each placement
    /// do.
    #[test]
    fn instances_answer_as_their_copies_do() {
        let (a, b) = (instanced(), copied());
        assert_eq!((a.primitive_count(), a.instance_count()), (1, 5));
        let mut uniform = crate::geometry::uniform_stream(0x2545_f491_4f6c_dd1du64);
        let mut next = move || uniform() * 2.0 - 1.0;
        let (mut hits, mut slab_hits) = (0, 0);
        for _ in 0..20_000 {
            let o = DVec3::new(next(), next(), next()) * 5.0;
            // Aimed at the placements' region, so most rays meet something.
            let aim = DVec3::new(next() * 3.0, next() * 3.5, next() * 3.0);
            let ray = Ray::new(o, (aim - o).normalize_or(DVec3::Y));
            let (ha, hb) = (a.intersect(&ray, 1e9, 0), b.intersect(&ray, 1e9, 0));
            assert_eq!(ha.is_some(), hb.is_some(), "{ray:?}");
            if let (Some(ha), Some(hb)) = (ha, hb) {
                hits += 1;
                assert!((ha.t - hb.t).abs() < 1e-9 * ha.t.max(1.0), "{ray:?}");
                let (sa, sb) = (a.surface(&ray, &ha), b.surface(&ray, &hb));
                assert!(
                    close(sa.normal, sb.normal),
                    "{:?} {:?}",
                    sa.normal,
                    sb.normal
                );
                assert_eq!(
                    (sa.material, a.hit_material(&ha)),
                    (sb.material, sb.material)
                );
                slab_hits += usize::from(sb.material == 99);
                let (ta, tb) = (a.texture_point(&ray, &ha), b.texture_point(&ray, &hb));
                assert!(close(ta.world, tb.world) && (ta.uv - tb.uv).length() < 1e-7);
            }
            assert_eq!(a.occluded(&ray, 1e9), b.occluded(&ray, 1e9), "{ray:?}");
            let crossings = |w: &World| {
                let mut n = 0;
                w.shadow_hits(&ray, 1e9, |_| {
                    n += 1;
                    true
                });
                n
            };
            assert_eq!(crossings(&a), crossings(&b), "{ray:?}");
            let inside = |w: &World| {
                let mut m: Vec<u32> = w.containing(o).collect();
                m.sort_unstable();
                m
            };
            assert_eq!(inside(&a), inside(&b), "{o}");
        }
        assert!(
            hits > 5_000,
            "{hits} hits: the test would not see a difference"
        );
        assert!(slab_hits > 500, "{slab_hits} hits on the cut slab");
    }
}
