//! The items that may stop the shadow rays inside a shaft ([`Shaft`]): one walk of the
//! tree for all of a shading point's rays towards an area light.

use std::cell::Cell;

use super::{Aabb, NO_TRANSFORM, Ray, Ref, ShapeKind, World, decode, flags};
use crate::geometry::Shaft;

/// Most items a shaft keeps: a shaft that meets more leaves its rays to walk the tree.
pub const MOST_OCCLUDERS: usize = 8;

/// The items whose boxes meet a shaft, with those boxes (a tree walked as a list gives an
/// item's own box; a larger tree its leaf's).
#[derive(Clone, Debug)]
pub struct Occluders {
    items: [u32; MOST_OCCLUDERS],
    boxes: [Aabb; MOST_OCCLUDERS],
    count: usize,
    /// The one that stopped the last stopped ray, tested first by the next: the rays from
    /// one point mostly meet the same object.
    first: Cell<usize>,
}

impl Occluders {
    /// Whether nothing can stop a ray inside the shaft.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }
}

impl World {
    /// The items that may cast a shadow on a ray inside `shaft`; `None` where more than
    /// [`MOST_OCCLUDERS`] may.
    pub fn shaft_occluders(&self, shaft: &Shaft) -> Option<Occluders> {
        let mut found = Occluders {
            items: [0; MOST_OCCLUDERS],
            boxes: [Aabb::EMPTY; MOST_OCCLUDERS],
            count: 0,
            first: Cell::new(0),
        };
        let mut keep = |item: u32, b: &Aabb| {
            if self.casts_no_shadow(item) {
                return true;
            }
            if found.count == MOST_OCCLUDERS {
                return false;
            }
            found.items[found.count] = item;
            found.boxes[found.count] = *b;
            found.count += 1;
            true
        };
        for (&item, extent) in self.unbounded.iter().zip(&self.unbounded_extents) {
            if shaft.misses(extent) || self.plane_beside(item, shaft) {
                continue;
            }
            if !keep(item, extent) {
                return None;
            }
        }
        if !self.bvh.each_meeting(|b| !shaft.misses(b), &mut keep) {
            return None;
        }
        Some(found)
    }

    /// Whether `item` is a primitive marked `no_shadow` (a light's visible bulb, placed
    /// where every shaft to the light meets it).
    fn casts_no_shadow(&self, item: u32) -> bool {
        matches!(decode(item), Ref::Primitive(i) if self.primitives[i].flags & flags::NO_SHADOW != 0)
    }

    /// Whether `item` is a plane the shaft lies wholly on one side of ([`Shaft::beside`]):
    /// the floor under a shading point, whose box (its half-space) every shaft from the
    /// floor meets.
    fn plane_beside(&self, item: u32, shaft: &Shaft) -> bool {
        let Ref::Primitive(i) = decode(item) else {
            return false;
        };
        let p = &self.primitives[i];
        match (&p.shape, p.transform) {
            (&ShapeKind::Plane { normal, distance }, NO_TRANSFORM) => {
                shaft.beside(normal, distance)
            }
            _ => false,
        }
    }

    /// [`World::occluded`] for a ray inside the shaft `among` came from: the same answer,
    /// from its items alone.
    pub fn occluded_among(&self, among: &Occluders, ray: &Ray, t_max: f64) -> bool {
        let inv = ray.direction.recip();
        let first = among.first.get();
        (first..among.count).chain(0..first).any(|k| {
            let blocks = among.boxes[k].hit(ray, inv, t_max).is_some()
                && self.item_blocks(among.items[k], ray, t_max);
            if blocks {
                among.first.set(k);
            }
            blocks
        })
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::geometry::{CsgOp, Transform, WorldBuilder};

    /// `count` spheres, intersections and differences of a box and a sphere, scattered
    /// over a cube of side 20, over a floor and under a tilted plane.
    fn scene(count: usize, next: &mut impl FnMut() -> f64) -> World {
        let mut b = WorldBuilder::default();
        let add = |b: &mut WorldBuilder, shape| b.primitive(shape, &Transform::IDENTITY, 0, 0);
        for k in 0..count {
            let c = DVec3::new(next(), next(), next()) * 20.0 - 10.0;
            let radius = 0.5 + next();
            let ball = add(&mut b, ShapeKind::Sphere { center: c, radius });
            let item = if k % 3 == 0 {
                ball
            } else {
                let (min, max) = (c - 1.0, c + DVec3::new(1.0, 0.6, 1.3));
                let cube = add(&mut b, ShapeKind::Box { min, max });
                let op = [CsgOp::Intersection, CsgOp::Difference][k % 3 - 1];
                b.csg(op, vec![cube, ball], false)
            };
            b.add_top(item);
        }
        for (normal, distance) in [(DVec3::Y, -11.0), (DVec3::new(0.3, 1.0, 0.2), 14.0)] {
            let plane = add(
                &mut b,
                ShapeKind::Plane {
                    normal: normal.normalize(),
                    distance,
                },
            );
            b.add_top(plane);
        }
        b.build()
    }

    /// Shadow rays from a point to points of a quadrilateral light, tested against the
    /// items of their shaft alone, are stopped exactly where a walk of the whole scene
    /// stops them; where no item meets the shaft, none is. Scenes walked as a list (3
    /// items and the 2 planes) and as a tree (60), shafts from points anywhere among the
    /// objects (inside some), lights large and small; every outcome occurs (empty shafts,
    /// kept items, too many).
    #[test]
    fn the_shafts_items_stop_exactly_the_rays_a_walk_finds_stopped() {
        let mut next = crate::geometry::uniform_stream(0x6a09_e667_f3bc_c908u64);
        let (mut empty, mut kept, mut full, mut blocked) = (0, 0, 0, 0);
        for count in [3, 60] {
            let world = scene(count, &mut next);
            for _ in 0..400 {
                let apex = DVec3::new(next(), next(), next()) * 24.0 - 12.0;
                let centre = DVec3::new(
                    next() * 20.0 - 10.0,
                    12.0 + next() * 4.0,
                    next() * 20.0 - 10.0,
                );
                let size = [0.01, 1.0, 6.0][(next() * 3.0) as usize];
                let (u, v) = (
                    DVec3::new(size, 0.0, next()),
                    DVec3::new(next(), next(), size),
                );
                let corners = [
                    centre - u - v,
                    centre + u - v,
                    centre + u + v,
                    centre - u + v,
                ];
                let Some(among) = world.shaft_occluders(&Shaft::new(apex, corners)) else {
                    full += 1;
                    continue;
                };
                if among.is_empty() {
                    empty += 1;
                } else {
                    kept += 1;
                }
                for _ in 0..50 {
                    let (a, b) = (next() * 2.0 - 1.0, next() * 2.0 - 1.0);
                    let to = centre + u * a + v * b - apex;
                    let ray = Ray::new(apex, to / to.length());
                    let t_max = to.length() * (1.0 - 1e-9);
                    let walk = world.occluded(&ray, t_max);
                    assert_eq!(world.occluded_among(&among, &ray, t_max), walk, "{ray:?}");
                    assert!(!walk || !among.is_empty());
                    blocked += usize::from(walk);
                }
            }
        }
        assert!(
            empty > 50 && kept > 50 && full > 20 && blocked > 1000,
            "{empty} empty, {kept} kept, {full} too many, {blocked} blocked"
        );
    }
}
