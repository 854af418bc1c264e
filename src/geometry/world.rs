//! The render-ready geometry: primitives with baked transforms, CSG nodes over them, a BVH
//! over the bounded top-level items, and the unbounded ones (planes, quadrics, inverses)
//! kept aside.

use std::cell::Cell;
use std::sync::Arc;

use glam::{DVec2, DVec3};

use super::bvh::NodeBox;
use super::polytope::{HalfSpace, polytope_extent};
use super::{
    Aabb, Bvh, LineInside, Ray, ShapeKind, ShapeTables, Transform, plane_hit, sphere_first_hit,
};

/// Per-primitive flags, tested as a mask so each kind of ray can skip some.
pub mod flags {
    pub const NO_SHADOW: u8 = 1;
    pub const NO_IMAGE: u8 = 2;
    pub const NO_REFLECTION: u8 = 4;
    /// Inside and outside swapped (POV-Ray's `inverse`).
    pub const INVERSE: u8 = 8;
    /// The material reads the surface's own (u, v) (`uv_mapping`); only then is it
    /// computed, so other scenes pay nothing for it.
    pub const UV: u8 = 16;
    /// Unseen by radiosity rays (`no_radiosity`).
    pub const NO_RADIOSITY: u8 = 32;
    /// Photons go through it unchanged (`photons { pass_through }`).
    pub const PHOTON_PASS: u8 = 64;
}

mod instance;
mod occluders;

pub use occluders::Occluders;

pub use instance::Instance;

const NO_TRANSFORM: u32 = u32::MAX;
/// Items (what the BVH and CSG nodes refer to) are primitives, CSG nodes with this bit, or
/// instances with [`INSTANCE_BIT`].
const CSG_BIT: u32 = 1 << 31;
const INSTANCE_BIT: u32 = 1 << 30;
/// A hit on the world's own primitives, not inside an instance.
pub const NO_INSTANCE: u32 = u32::MAX;
/// No item (as an item number, the CSG node 2^31 - 1, which no world holds).
pub const NO_ITEM: u32 = u32::MAX;

/// What an item number names.
#[derive(Clone, Copy)]
enum Ref {
    Primitive(usize),
    Csg(usize),
    Instance(usize),
}

#[inline]
fn decode(item: u32) -> Ref {
    if item & CSG_BIT != 0 {
        Ref::Csg((item & !CSG_BIT) as usize)
    } else if item & INSTANCE_BIT != 0 {
        Ref::Instance((item & !INSTANCE_BIT) as usize)
    } else {
        Ref::Primitive(item as usize)
    }
}

/// What the render-ready scene takes per primitive at its peak (while its BVH is built):
/// the primitive, its bounds, the tree's share and its place in the scene's order. The
/// scene language charges each object this much beside its own size against the memory
/// budget, so the budget bounds the whole process, not only the scene model.
pub const PREPARED_BYTES_PER_PRIMITIVE: usize = size_of::<Primitive>()
    + size_of::<Aabb>()
    + super::bvh::BYTES_PER_ITEM
    + size_of::<(u32, u32)>();

#[derive(Clone, Copy, Debug)]
pub struct Primitive {
    pub shape: ShapeKind,
    /// Index into `World::transforms`, or `NO_TRANSFORM` when the shape is in world space.
    transform: u32,
    pub material: u32,
    pub flags: u8,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgOp {
    Union,
    Merge,
    Intersection,
    Difference,
    /// The first child's surface, kept where it is inside every other child (`clipped_by`).
    Clip,
    /// The first child, for rays that meet every other child or start inside it
    /// (`bounded_by` as POV-Ray applies it: a test of the ray, not of the hit point).
    Bound,
}

#[derive(Clone, Debug)]
struct CsgNode {
    op: CsgOp,
    children: Vec<u32>,
    inverse: bool,
    index: Option<Box<ChildIndex>>,
    /// An intersection or a clip with a child that searches the line for its crossings
    /// (a quartic, a poly): its convex children's spans narrow that search
    /// ([`World::kept_window`]). Elsewhere finding the spans would only double the work.
    windowed: bool,
    /// The box a ray must meet for the node to be searched ([`World::csg_meets`]): its
    /// extent rounded outward to single precision, as the tree's boxes are. None where the
    /// node is unbounded, or a list walk has just tested the same box.
    own_box: Option<NodeBox>,
}

/// Past this many children a CSG node indexes them by their boxes, so that a ray or a
/// point meets only the children near it: a slab with 2,500 holes otherwise tested every
/// hole for every ray, and every hole again for every hit. A node of fewer is indexed
/// where its children lie apart ([`World::small_index`]).
const INDEXED_CHILDREN: usize = 8;

/// A small node's index costs a ray its set-up (the ray's reciprocals and the walk: about
/// 50 instructions) and a box test a child (about 30), in the units of
/// [`World::crossing_cost`].
const INDEX_SETUP: f64 = 0.5;
const INDEX_BOX: f64 = 0.3;

/// A transformed primitive's crossings cost about three times an untransformed one's
/// (mist's transformed boxes and cylinders: 350 instructions a child, against 80 for a
/// box without a transform).
const TRANSFORMED_COST: f64 = 3.0;

/// A CSG node's children in a BVH of their own; its items are positions among the
/// children. Children without a box to trust (unbounded, or holding a `bounded_by`, whose
/// box limits rays rather than the solid) are always tested.
#[derive(Clone, Debug)]
struct ChildIndex {
    /// The first position indexed: 1 in a difference, whose first child is always tested.
    first: usize,
    bvh: Bvh,
    unbounded: Vec<u32>,
}

/// A reference to something the world can intersect: a primitive or a CSG node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Item(u32);

#[derive(Clone, Copy, Debug)]
pub struct Hit {
    pub t: f64,
    pub primitive: u32,
    /// Which piece of the primitive: a mesh's face, a height field's triangle (else 0).
    pub part: u32,
    /// The surface's outward side is reversed (the subtracted part of a difference, or an
    /// inverse object).
    pub flipped: bool,
    /// The instance whose prototype holds `primitive` ([`NO_INSTANCE`]: the world's own).
    pub instance: u32,
}

/// Where a ray met a surface, in world space.
#[derive(Clone, Copy, Debug)]
pub struct SurfacePoint {
    pub point: DVec3,
    /// Outward geometric normal, unit length.
    pub normal: DVec3,
    /// The normal for shading (interpolated on smooth triangles), unit, on the same side.
    pub shading_normal: DVec3,
    pub material: u32,
    /// The surface's own (u, v) where the material asks for it (`flags::UV`), else the
    /// world x and y, which is what povray uses for shapes without a uv mapping.
    pub uv: DVec2,
    /// A mesh face with a texture per corner: POV-Ray shows the corners' textures mixed by
    /// the point's barycentric weights.
    pub blend: Option<MaterialBlend>,
}

/// A surface whose texture is a mix of materials at the point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MaterialBlend {
    /// A mesh face's corner materials and the point's barycentric weights.
    Corners {
        materials: [u32; 3],
        weights: [f64; 3],
    },
    /// A blob with textured components, at `local`, a point in its own space.
    Blob { blob: u32, own: u32, local: DVec3 },
}

/// Where a texture is looked up: the world point, and the surface's (u, v) for patterns
/// with `uv_mapping`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexturePoint {
    pub world: DVec3,
    pub uv: DVec2,
    /// The unit shading normal facing the viewer, for `slope`; zero where none is known.
    pub normal: DVec3,
}

impl From<DVec3> for TexturePoint {
    /// A point with no surface behind it: uv falls back to x and y as in povray.
    fn from(world: DVec3) -> TexturePoint {
        TexturePoint {
            world,
            uv: world.truncate(),
            normal: DVec3::ZERO,
        }
    }
}

impl From<&SurfacePoint> for TexturePoint {
    fn from(s: &SurfacePoint) -> TexturePoint {
        TexturePoint {
            world: s.point,
            uv: s.uv,
            normal: s.shading_normal,
        }
    }
}

#[derive(Clone, Debug, Default)]
pub struct World {
    primitives: Vec<Primitive>,
    transforms: Vec<Transform>,
    tables: ShapeTables,
    csg: Vec<CsgNode>,
    /// Each CSG node's extent ([`World::item_extent`]), found once at the build: the box
    /// of an intersection of turned planes takes a search of their vertices (about 120,000
    /// instructions for a dodecahedron's twelve), and the builds ask for a node's extent
    /// several times (the tree's items, its parent's).
    csg_extents: Vec<Aabb>,
    bvh: Bvh,
    unbounded: Vec<u32>,
    /// The unbounded items' extents (infinite on some sides), for shafts
    /// ([`World::shaft_occluders`]).
    unbounded_extents: Vec<Aabb>,
    /// Each top-level item's place in the scene's order, sorted by item: of two bounded
    /// surfaces met at the same distance, the one declared first is seen, whatever the
    /// tree's shape (advanced/pawns' rosewood squares, declared before the pine board their
    /// tops are flush with; POV-Ray speckles between the two there). Read only on ties.
    declared: Vec<(u32, u32)>,
    /// The bounds of the objects photons are shot at (`photons { target }`).
    photon_targets: Vec<Aabb>,
    instances: Vec<Instance>,
}

/// Collects primitives and CSG nodes, then builds the BVH over the top-level items.
#[derive(Default)]
pub struct WorldBuilder {
    primitives: Vec<Primitive>,
    transforms: Vec<Transform>,
    pub tables: ShapeTables,
    csg: Vec<CsgNode>,
    top: Vec<Item>,
    targets: Vec<Item>,
    instances: Vec<Instance>,
}

impl WorldBuilder {
    /// Adds a shape placed by `transform`; simple placements are baked into the shape.
    pub fn primitive(
        &mut self,
        shape: ShapeKind,
        transform: &Transform,
        material: u32,
        flags: u8,
    ) -> Item {
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
        Item((self.primitives.len() - 1) as u32)
    }

    pub fn csg(&mut self, op: CsgOp, children: Vec<Item>, inverse: bool) -> Item {
        self.csg.push(CsgNode {
            op,
            children: children.into_iter().map(|i| i.0).collect(),
            inverse,
            index: None,
            windowed: false,
            own_box: None,
        });
        Item((self.csg.len() - 1) as u32 | CSG_BIT)
    }

    /// A prototype's world placed by `transform` (prototype to world), its materials
    /// numbered from `materials` on.
    pub fn instance(&mut self, world: Arc<World>, transform: Transform, materials: u32) -> Item {
        self.instances
            .push(Instance::new(world, transform, materials));
        Item((self.instances.len() - 1) as u32 | INSTANCE_BIT)
    }

    /// Makes an item part of the scene (not only a CSG child).
    pub fn add_top(&mut self, item: Item) {
        self.top.push(item);
    }

    /// Marks an item as a target photons are shot at.
    pub fn add_photon_target(&mut self, item: Item) {
        self.targets.push(item);
    }

    pub fn build(self) -> World {
        let mut world = World {
            primitives: self.primitives,
            transforms: self.transforms,
            tables: self.tables,
            csg: self.csg,
            csg_extents: Vec::new(),
            bvh: Bvh::default(),
            unbounded: Vec::new(),
            unbounded_extents: Vec::new(),
            declared: (0..).zip(&self.top).map(|(k, i)| (i.0, k)).collect(),
            photon_targets: Vec::new(),
            instances: self.instances,
        };
        // In the builder's order, so that a node's children are found in the table.
        world.csg_extents = Vec::with_capacity(world.csg.len());
        for k in 0..world.csg.len() {
            let extent = world.csg_extent(&world.csg[k]);
            world.csg_extents.push(extent);
        }
        for (node, extent) in world.csg.iter_mut().zip(&world.csg_extents) {
            node.own_box = extent.bounded().map(|b| NodeBox::enclosing(&b));
        }
        world.index_csg_children();
        world.photon_targets = self
            .targets
            .iter()
            .filter_map(|item| world.item_bounds(item.0))
            .filter(|b| b.is_finite() && !b.is_empty())
            .collect();
        let (bvh, unbounded) = world.bvh_over(self.top.iter().map(|i| (i.0, i.0)), |_| true);
        world.bvh = bvh;
        world.unbounded = unbounded;
        world.primitives_in_leaf_order();
        if world.bvh.walks_as_list() {
            for item in &self.top {
                if let Ref::Csg(k) = decode(item.0) {
                    world.csg[k].own_box = None;
                }
            }
        }
        world.unbounded_extents = world
            .unbounded
            .iter()
            .map(|&i| world.item_extent(i))
            .collect();
        world
    }
}

/// Moves each element `i` to `dest[i]` (a permutation), cycle by cycle, without a copy of
/// the slice; `dest` ends as the identity.
fn permute<T>(v: &mut [T], dest: &mut [u32]) {
    for i in 0..v.len() {
        while dest[i] as usize != i {
            let j = dest[i] as usize;
            v.swap(i, j);
            dest.swap(i, j);
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
            let p = t.point(normal * (distance / normal.length_squared()));
            let n = n / n.length();
            Some(ShapeKind::Plane {
                normal: n,
                distance: n.dot(p),
            })
        }
        _ => None,
    }
}

impl World {
    fn index_csg_children(&mut self) {
        use rayon::prelude::*;
        // Each node's index is its own small build (10^5 small nodes: 0.3 s on one core).
        let found: Vec<(Option<ChildIndex>, bool)> = self
            .csg
            .par_iter()
            .map(|node| (self.child_index(node), self.searches_within(node)))
            .collect();
        for (node, (index, windowed)) in self.csg.iter_mut().zip(found) {
            node.index = index.map(Box::new);
            node.windowed = windowed;
        }
    }

    /// Whether an intersection or a clip holds a quartic or a poly where its crossings
    /// count (a clip's first child, any child of an intersection).
    fn searches_within(&self, node: &CsgNode) -> bool {
        let counted = match node.op {
            CsgOp::Intersection => &node.children[..],
            CsgOp::Clip => &node.children[..1],
            _ => return false,
        };
        counted.iter().any(|&c| match decode(c) {
            Ref::Primitive(i) => matches!(
                self.primitives[i].shape,
                ShapeKind::Quartic(_) | ShapeKind::Poly(_)
            ),
            _ => false,
        })
    }

    fn child_index(&self, node: &CsgNode) -> Option<ChildIndex> {
        let first = match node.op {
            CsgOp::Union | CsgOp::Merge => 0,
            // Subtracting a surface without a solid keeps nothing anywhere: the scan
            // handles that.
            CsgOp::Difference if node.children[1..].iter().all(|&c| self.has_inside(c)) => 1,
            _ => return None,
        };
        if node.children.len() <= first + INDEXED_CHILDREN {
            return self.small_index(node, first);
        }
        let positions = node.children.iter().enumerate().skip(first);
        let (bvh, unbounded) = self.bvh_over(positions.map(|(j, &c)| (j as u32, c)), |c| {
            !self.holds_bound(c)
        });
        Some(ChildIndex {
            first,
            bvh,
            unbounded,
        })
    }

    /// The index of a node of few children (a list of their boxes, in their order) where it
    /// saves a ray more than it costs: the children's boxes the ray misses, by the share of
    /// the node's box surface each leaves uncovered (the chance that a ray meeting the node
    /// misses it), weighed by what finding the child's crossings costs
    /// ([`World::crossing_cost`]), against the index's own walk: [`INDEX_SETUP`] and
    /// [`INDEX_BOX`] a child.
    fn small_index(&self, node: &CsgNode, first: usize) -> Option<ChildIndex> {
        let boxes: Vec<Option<Aabb>> = node
            .children
            .iter()
            .map(|&c| {
                let trusted = !self.holds_bound(c);
                self.item_bounds(c)
                    .filter(|b| trusted && b.is_finite() && !b.is_empty())
            })
            .collect();
        // Rays reach the node through its own box: a difference's is its first child's.
        // Where that is unbounded, the box of the bounded children stands for it (which
        // makes a miss look less likely than it is).
        let bounded = boxes.iter().flatten().fold(Aabb::EMPTY, |a, b| a.union(b));
        let whole = match boxes[0] {
            Some(b) if node.op == CsgOp::Difference => b,
            _ => bounded,
        };
        let area = whole.surface_area();
        if area.is_nan() || area <= 0.0 {
            return None;
        }
        let (mut saved, mut listed, mut labels, mut unbounded) =
            (0.0, Vec::new(), Vec::new(), Vec::new());
        for (j, (b, &c)) in boxes.iter().zip(&node.children).enumerate().skip(first) {
            match b {
                Some(b) => {
                    let missed = 1.0 - b.intersection(&whole).surface_area() / area;
                    saved += missed * self.crossing_cost(c);
                    listed.push(*b);
                    labels.push(j as u32);
                }
                None => unbounded.push(j as u32),
            }
        }
        if saved <= INDEX_SETUP + INDEX_BOX * labels.len() as f64 {
            return None;
        }
        let bvh = Bvh::list(labels, |k| listed[k])?;
        Some(ChildIndex {
            first,
            bvh,
            unbounded,
        })
    }

    /// What finding an item's crossings costs a ray, in units of a primitive placed
    /// without a transform of its own (about 100 instructions: a box, 80; a sphere's
    /// quadratic, fewer): a transformed or instanced one [`TRANSFORMED_COST`], a CSG node
    /// its children's sum.
    fn crossing_cost(&self, item: u32) -> f64 {
        match decode(item) {
            Ref::Primitive(i) if self.primitives[i].transform == NO_TRANSFORM => 1.0,
            Ref::Primitive(_) | Ref::Instance(_) => TRANSFORMED_COST,
            Ref::Csg(k) => self.csg[k]
                .children
                .iter()
                .map(|&c| self.crossing_cost(c))
                .sum(),
        }
    }

    /// A BVH over the items with finite bounds that `trusted` accepts, its leaves holding
    /// each item's label, and the labels of the others (to be tested always). The bounds
    /// are computed again for the build rather than kept: an array of them would be the
    /// build's largest after the primitives.
    fn bvh_over(
        &self,
        items: impl Iterator<Item = (u32, u32)>,
        trusted: impl Fn(u32) -> bool,
    ) -> (Bvh, Vec<u32>) {
        let mut bounded = Vec::new();
        let mut unbounded = Vec::new();
        for (label, item) in items {
            match self.item_bounds(item) {
                Some(b) if b.is_finite() && !b.is_empty() && trusted(item) => {
                    bounded.push((label, item));
                }
                _ => unbounded.push(label),
            }
        }
        let bounds_of = |i: usize| self.item_bounds(bounded[i].1).unwrap_or(Aabb::EMPTY);
        if let Some(list) = Bvh::list(bounded.iter().map(|b| b.0).collect(), bounds_of) {
            return (list, unbounded);
        }
        let mut bvh = Bvh::build_from(bounded.len(), bounds_of);
        for leaf in &mut bvh.items {
            *leaf = bounded[*leaf as usize].0;
        }
        (bvh, unbounded)
    }

    /// Whether the item is or holds a `bounded_by` node.
    fn holds_bound(&self, item: u32) -> bool {
        match decode(item) {
            Ref::Primitive(_) => false,
            Ref::Instance(k) => self.instances[k].holds_bound(),
            Ref::Csg(k) => {
                let node = &self.csg[k];
                node.op == CsgOp::Bound || node.children.iter().any(|&c| self.holds_bound(c))
            }
        }
    }

    /// Whether an indexed child other than the one at `except` holds `p`.
    fn indexed_child_holds(
        &self,
        node: &CsgNode,
        index: &ChildIndex,
        p: DVec3,
        except: usize,
    ) -> bool {
        let holds = |j: u32| j as usize != except && self.inside(node.children[j as usize], p);
        index.unbounded.iter().any(|&j| holds(j)) || index.bvh.any_containing(p, holds)
    }

    /// Renumbers the primitives so those the BVH's leaves name directly come in leaf order:
    /// neighbours in space become neighbours in memory, which keeps traversal of large
    /// scenes in cache. Every reference (leaves, CSG children, unbounded list) is remapped.
    fn primitives_in_leaf_order(&mut self) {
        let n = self.primitives.len();
        let mut new_index = vec![u32::MAX; n];
        let mut placed = 0u32;
        for &item in &self.bvh.items {
            if matches!(decode(item), Ref::Primitive(_)) && new_index[item as usize] == u32::MAX {
                new_index[item as usize] = placed;
                placed += 1;
            }
        }
        for slot in new_index.iter_mut().filter(|s| **s == u32::MAX) {
            *slot = placed;
            placed += 1;
        }
        // In place: a reordered copy would double the largest array at the peak.
        permute(&mut self.primitives, &mut new_index.clone());
        let remap = |item: &mut u32| {
            if let Ref::Primitive(i) = decode(*item) {
                *item = new_index[i];
            }
        };
        self.bvh.items.iter_mut().for_each(remap);
        self.unbounded.iter_mut().for_each(remap);
        self.declared.iter_mut().for_each(|(item, _)| remap(item));
        self.declared.sort_unstable();
        for node in &mut self.csg {
            node.children.iter_mut().for_each(remap);
        }
        if (0..).zip(&self.bvh.items).all(|(k, &item)| item == k) {
            self.bvh.items_in_leaf_order();
        }
    }

    /// The bounds of the photon targets (infinite ones left out: nothing to aim at).
    pub fn photon_targets(&self) -> &[Aabb] {
        &self.photon_targets
    }

    pub fn primitive_count(&self) -> usize {
        self.primitives.len()
    }

    /// Warnings about isosurfaces steeper than their max_gradient, after a render.
    pub fn gradient_notes(&self) -> Vec<String> {
        let mut notes = self.tables.gradient_notes();
        notes.extend(self.prototypes().flat_map(World::gradient_notes));
        notes
    }

    /// Bytes held by the geometry's arrays (primitives, transforms, shape tables' headers,
    /// CSG nodes, BVH nodes and item list, instances and their prototypes once), for the
    /// benchmark's memory per object.
    pub fn memory_bytes(&self) -> usize {
        use std::mem::size_of;
        self.primitives.capacity() * size_of::<Primitive>()
            + self.transforms.capacity() * size_of::<Transform>()
            + self.csg.capacity() * size_of::<CsgNode>()
            + self.csg_extents.capacity() * size_of::<Aabb>()
            + self
                .csg
                .iter()
                .map(|c| c.children.capacity() * 4)
                .sum::<usize>()
            + self.bvh.nodes.capacity() * size_of::<super::bvh::Node>()
            + self.bvh.items.capacity() * 4
            + self.unbounded.capacity() * 4
            + self.unbounded_extents.capacity() * size_of::<Aabb>()
            + self.declared.capacity() * size_of::<(u32, u32)>()
            + self.tables.memory_bytes()
            + self.instances.capacity() * size_of::<Instance>()
            + self.prototypes().map(World::memory_bytes).sum::<usize>()
    }

    /// Each prototype the instances share, once.
    fn prototypes(&self) -> impl Iterator<Item = &World> {
        let mut seen = std::collections::HashSet::new();
        self.instances
            .iter()
            .map(|i| &**i.prototype())
            .filter(move |w| seen.insert(*w as *const World))
    }

    /// The instances placed in the scene (not counting their prototypes' primitives).
    pub fn instance_count(&self) -> usize {
        self.instances.len()
    }

    /// Whether the world holds textured blobs, whose blend reads this world's own tables.
    pub fn has_textured_blobs(&self) -> bool {
        self.tables.blobs.iter().any(|b| b.textured)
    }

    fn item_bounds(&self, item: u32) -> Option<Aabb> {
        self.item_extent(item).bounded()
    }

    /// The box around an item's solid, its sides infinite where the solid is unbounded
    /// that way: an intersection or a clip of unbounded children can be bounded.
    fn item_extent(&self, item: u32) -> Aabb {
        match decode(item) {
            Ref::Primitive(i) => self.primitive_extent(&self.primitives[i]),
            Ref::Instance(k) => self.instances[k].bounds().unwrap_or(Aabb::INFINITE),
            Ref::Csg(k) => match self.csg_extents.get(k) {
                Some(&extent) => extent,
                None => self.csg_extent(&self.csg[k]),
            },
        }
    }

    /// [`World::item_extent`] of a CSG node, from its children's.
    fn csg_extent(&self, node: &CsgNode) -> Aabb {
        if node.inverse {
            return Aabb::INFINITE;
        }
        let mut children = node.children.iter().map(|&c| self.item_extent(c));
        match node.op {
            CsgOp::Union | CsgOp::Merge => children.fold(Aabb::EMPTY, |acc, b| acc.union(&b)),
            CsgOp::Difference => children.next().unwrap_or(Aabb::INFINITE),
            // POV-Ray bounds the object by its bounds' box (as `max_extent` shows), and
            // its traversal then culls by that box too; only quartics and polys keep
            // their bounds, and those are unbounded themselves.
            CsgOp::Bound => {
                let own = children.next().unwrap_or(Aabb::INFINITE);
                let bounds = node.children[1..]
                    .iter()
                    .map(|&c| self.item_bounds(c))
                    .try_fold(None, |acc: Option<Aabb>, b| {
                        let b = b?;
                        Some(Some(acc.map_or(b, |a| a.intersection(&b))))
                    })
                    .flatten();
                bounds.unwrap_or(own)
            }
            // Each child limits the whole, turned planes by the polytope they make.
            CsgOp::Intersection | CsgOp::Clip => {
                let boxed = children.fold(Aabb::INFINITE, |acc, b| acc.intersection(&b));
                self.cut_by_half_spaces(node, boxed)
            }
        }
    }

    /// The part of an intersection's or a clip's box inside its plane children's
    /// half-spaces (a clip's clipped plane too: its surface lies on its half-space's
    /// side), where one of them is turned off the axes (an axis-aligned one's half-space
    /// is its extent already).
    fn cut_by_half_spaces(&self, node: &CsgNode, boxed: Aabb) -> Aabb {
        let half_spaces: Vec<HalfSpace> = node
            .children
            .iter()
            .filter_map(|&c| match decode(c) {
                Ref::Primitive(i) => self.half_space(&self.primitives[i]),
                _ => None,
            })
            .collect();
        let turned = |h: &HalfSpace| h.normal.abs().max_element() < 1.0;
        if !half_spaces.iter().any(turned) {
            return boxed;
        }
        polytope_extent(&half_spaces, boxed)
    }

    /// A plane primitive's solid in world space.
    fn half_space(&self, p: &Primitive) -> Option<HalfSpace> {
        let world = match p.transform {
            NO_TRANSFORM => p.shape,
            t => bake(p.shape, &self.transforms[t as usize])?,
        };
        let ShapeKind::Plane { normal, distance } = world else {
            return None;
        };
        let h = HalfSpace::new(normal, distance);
        Some(if p.flags & flags::INVERSE != 0 {
            h.flipped()
        } else {
            h
        })
    }

    fn primitive_extent(&self, p: &Primitive) -> Aabb {
        if p.flags & flags::INVERSE != 0 {
            return Aabb::INFINITE;
        }
        let extent = p.shape.extent(&self.tables);
        match p.transform {
            NO_TRANSFORM => extent,
            t => extent.transformed_extent(&self.transforms[t as usize]),
        }
    }

    #[inline]
    fn local_ray(&self, p: &Primitive, ray: &Ray) -> Ray {
        if p.transform == NO_TRANSFORM {
            *ray
        } else {
            self.transforms[p.transform as usize].inverse_ray(ray)
        }
    }

    /// The nearest hit of one item in (0, t_max). Primitives, most of what leaves hold,
    /// take an inlined path; CSG nodes and instances the general one.
    #[inline(always)]
    fn item_hit(&self, item: u32, ray: &Ray, t_max: f64, skip: u8) -> Option<Hit> {
        match decode(item) {
            Ref::Primitive(i) => self.primitive_hit(i, ray, t_max, skip),
            _ => self.composite_hit(item, ray, t_max, skip),
        }
    }

    #[inline(always)]
    fn primitive_hit(&self, i: usize, ray: &Ray, t_max: f64, skip: u8) -> Option<Hit> {
        let p = &self.primitives[i];
        if p.flags & skip != 0 {
            return None;
        }
        // A world-space shape reads the ray in place rather than a copy of it; a sphere
        // and a plane, the commonest (every shadow ray tests a scene's floor), skip the
        // shapes' dispatch and its call (reflection: 44 instructions a plane test, 19 of
        // them the call's).
        let (t, part) = match (&p.shape, p.transform) {
            (&ShapeKind::Sphere { center, radius }, NO_TRANSFORM) => {
                (sphere_first_hit(ray, center, radius, t_max)?, 0)
            }
            (&ShapeKind::Plane { normal, distance }, NO_TRANSFORM) => {
                (plane_hit(ray, normal, distance, t_max)?, 0)
            }
            (shape, NO_TRANSFORM) => shape.intersect_part(ray, t_max, &self.tables)?,
            (shape, transform) => {
                let local = self.transforms[transform as usize].inverse_ray(ray);
                shape.intersect_part(&local, t_max, &self.tables)?
            }
        };
        Some(Hit {
            t,
            primitive: i as u32,
            part,
            flipped: p.flags & flags::INVERSE != 0,
            instance: NO_INSTANCE,
        })
    }

    /// The nearest hit of a CSG node or an instance in (0, t_max).
    #[inline(never)]
    fn composite_hit(&self, item: u32, ray: &Ray, t_max: f64, skip: u8) -> Option<Hit> {
        if let Ref::Instance(k) = decode(item) {
            return self.instances[k].hit(k as u32, ray, t_max, skip);
        }
        let mut best: Option<Hit> = None;
        let reach = Cell::new(t_max);
        self.for_each_hit(item, ray, (0.0, t_max), skip, &reach, &mut |hit| {
            if hit.t < reach.get() {
                reach.set(hit.t);
                best = Some(hit);
            }
        });
        best
    }

    /// Every visible surface crossing of an item in (0, t_max), in no particular order, but
    /// those at or beyond `reach`: a nearest-hit query shrinks it to the nearest hit found,
    /// so that a CSG node tests no point beyond it against its other children (wood_18's
    /// intersections of a box and two cylinders: three quarters of their crossings lie
    /// behind the first).
    fn for_each_hit(
        &self,
        item: u32,
        ray: &Ray,
        within: (f64, f64),
        skip: u8,
        reach: &Cell<f64>,
        f: &mut dyn FnMut(Hit),
    ) {
        let node = match decode(item) {
            Ref::Primitive(i) if self.primitives[i].shape.finds_crossings_in_order() => {
                return self.ordered_hits(i, ray, within, skip, reach, f);
            }
            Ref::Primitive(i) => return self.primitive_hits(i, ray, within, skip, f),
            Ref::Instance(k) => {
                return self.instances[k].for_each_hit(k as u32, ray, within.1, skip, f);
            }
            Ref::Csg(k) if self.csg_meets(k, ray, within.1) => &self.csg[k],
            Ref::Csg(_) => return,
        };
        if node.op == CsgOp::Bound {
            if self.ray_meets_bounds(&node.children[1..], ray) {
                self.for_each_hit(node.children[0], ray, within, skip, reach, f);
            }
            return;
        }
        let within = if node.windowed {
            match self.kept_window(node, ray, within) {
                Some(w) => w,
                None => return,
            }
        } else {
            within
        };
        let t_max = within.1;
        let visit = |i: usize, f: &mut dyn FnMut(Hit)| {
            self.for_each_hit(
                node.children[i],
                ray,
                within,
                skip,
                reach,
                &mut |hit: Hit| {
                    if hit.t >= reach.get() {
                        return;
                    }
                    if node.op == CsgOp::Union {
                        f(hit);
                    } else if self.kept(node, i, ray.at(hit.t)) {
                        let subtracted = node.op == CsgOp::Difference && i > 0;
                        f(Hit {
                            flipped: hit.flipped ^ subtracted ^ node.inverse,
                            ..hit
                        });
                    }
                },
            );
        };
        match &node.index {
            // Only the children whose boxes the ray meets can be hit.
            Some(index) => {
                (0..index.first).for_each(|i| visit(i, f));
                index.unbounded.iter().for_each(|&j| visit(j as usize, f));
                index.bvh.traverse(ray, t_max, |j, t| {
                    visit(j as usize, f);
                    Some(t)
                });
            }
            None if node.op == CsgOp::Clip => visit(0, f),
            None => (0..node.children.len()).for_each(|i| visit(i, f)),
        }
    }

    /// Whether a ray meets a CSG node's box within (0, t_max). A leaf of the tree holds up
    /// to four items, and a ray that meets the leaf's box misses most of its items' boxes,
    /// where a node's crossings cost far more than its box: whiltile's tiles (a box, two
    /// cylinders and a sphere, turned and placed) about 1,700 instructions a ray. The box
    /// is rounded outward to single precision, as the tree's, so the test passes every ray
    /// the tree passes to the node that can cross it.
    #[inline]
    fn csg_meets(&self, k: usize, ray: &Ray, t_max: f64) -> bool {
        self.csg[k]
            .own_box
            .is_none_or(|b| b.aabb().hit(ray, ray.direction.recip(), t_max).is_some())
    }

    /// The part of `within` where a crossing of an intersection or a clip can be kept:
    /// inside every convex primitive that must hold it (an intersection's children, a
    /// clip's clipping ones), found from where the line crosses them. A quartic clipped by
    /// a cylinder and two planes (shapesq.inc's) then searches a few units of the line for
    /// its roots, not all of it. None where that part is empty.
    fn kept_window(
        &self,
        node: &CsgNode,
        ray: &Ray,
        (mut lo, mut hi): (f64, f64),
    ) -> Option<(f64, f64)> {
        let first = usize::from(node.op == CsgOp::Clip);
        for &c in &node.children[first..] {
            let Ref::Primitive(i) = decode(c) else {
                continue;
            };
            let p = &self.primitives[i];
            if p.flags & flags::INVERSE != 0 {
                continue;
            }
            match p.shape.line_inside(&self.local_ray(p, ray), &self.tables) {
                LineInside::Unknown => {}
                LineInside::Never => return None,
                LineInside::Between(a, b) => {
                    // Wide of the crossings' rounding (a near-tangent quadric's is the
                    // square root of the unit roundoff's).
                    let slack = 1e-6
                        * [a, b]
                            .iter()
                            .filter(|t| t.is_finite())
                            .fold(0.0, |m: f64, t| m.max(t.abs()));
                    lo = lo.max(a - slack);
                    hi = hi.min(b + slack);
                }
            }
        }
        (lo < hi).then_some((lo, hi))
    }

    /// The crossings of a primitive within (lo, hi) (lo at least 0).
    fn primitive_hits(
        &self,
        i: usize,
        ray: &Ray,
        (lo, hi): (f64, f64),
        skip: u8,
        f: &mut dyn FnMut(Hit),
    ) {
        let p = &self.primitives[i];
        if p.flags & skip != 0 {
            return;
        }
        let flipped = p.flags & flags::INVERSE != 0;
        p.shape.each_hit_part_within(
            &self.local_ray(p, ray),
            &self.tables,
            (lo, hi),
            |t, part| {
                if t > lo && t < hi {
                    f(Hit {
                        t,
                        primitive: i as u32,
                        part,
                        flipped,
                        instance: NO_INSTANCE,
                    });
                }
            },
        );
    }

    /// [`World::primitive_hits`] of a shape that searches for its crossings in order
    /// ([`ShapeKind::finds_crossings_in_order`]), which stops at `reach`
    /// ([`World::for_each_hit`]): a nearest-hit query through a CSG node wants none
    /// beyond the nearest found (stackergold's isosurfaces, met ahead of a ray, had their
    /// far side searched through the whole container). Out of line, so that the common
    /// primitives' path through [`World::for_each_hit`] stays as it was.
    #[inline(never)]
    fn ordered_hits(
        &self,
        i: usize,
        ray: &Ray,
        (lo, hi): (f64, f64),
        skip: u8,
        reach: &Cell<f64>,
        f: &mut dyn FnMut(Hit),
    ) {
        let p = &self.primitives[i];
        if p.flags & skip != 0 {
            return;
        }
        let flipped = p.flags & flags::INVERSE != 0;
        p.shape
            .crossings_from(&self.local_ray(p, ray), &self.tables, lo, |t| {
                if t > lo && t < hi {
                    f(Hit {
                        t,
                        primitive: i as u32,
                        part: 0,
                        flipped,
                        instance: NO_INSTANCE,
                    });
                }
                t < hi && t < reach.get()
            });
    }

    /// Whether a hit at `p` on the child at `i` is on the node's surface, from where `p`
    /// lies in the other children.
    fn kept(&self, node: &CsgNode, i: usize, p: DVec3) -> bool {
        if let Some(index) = &node.index {
            let others_hold = self.indexed_child_holds(node, index, p, i);
            return match node.op {
                CsgOp::Merge => !others_hold,
                CsgOp::Difference => !others_hold && (i == 0 || self.inside(node.children[0], p)),
                _ => true,
            };
        }
        let mut others = node
            .children
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(j, &c)| (j, self.inside(c, p)));
        match node.op {
            CsgOp::Union | CsgOp::Bound => true,
            CsgOp::Merge => others.all(|(_, inside)| !inside),
            CsgOp::Intersection | CsgOp::Clip => others.all(|(_, inside)| inside),
            CsgOp::Difference => others.all(|(j, inside)| {
                if j == 0 {
                    inside
                } else {
                    !inside && self.has_inside(node.children[j])
                }
            }),
        }
    }

    /// Whether the item is a solid at all. Surfaces without one (triangles, polygons,
    /// bicubic patches, meshes without an inside vector) hold no point even turned inside
    /// out, so subtracting one keeps nothing of the other children (measured: a box minus
    /// a triangle shows only the triangle's part in the box, as box and triangle
    /// intersected do).
    fn has_inside(&self, item: u32) -> bool {
        let Ref::Primitive(i) = decode(item) else {
            return true;
        };
        match self.primitives[i].shape {
            ShapeKind::Triangle(_) | ShapeKind::Polygon(_) => false,
            ShapeKind::Mesh(i) => self.tables.meshes[i as usize].inside_vector.is_some(),
            _ => true,
        }
    }

    /// Whether a world point is inside an item's solid.
    pub fn inside(&self, item: u32, p: DVec3) -> bool {
        let node = match decode(item) {
            Ref::Primitive(i) => {
                if !self.has_inside(item) {
                    return false;
                }
                let prim = &self.primitives[i];
                let local = self.local_point(prim, p);
                return prim.shape.inside(local, &self.tables) ^ (prim.flags & flags::INVERSE != 0);
            }
            Ref::Instance(k) => return self.instances[k].holds(p),
            Ref::Csg(k) => &self.csg[k],
        };
        if let Some(index) = &node.index {
            let any = self.indexed_child_holds(node, index, p, usize::MAX);
            let inside = match node.op {
                CsgOp::Difference => !any && self.inside(node.children[0], p),
                _ => any,
            };
            return inside ^ node.inverse;
        }
        let mut children = node.children.iter().map(|&c| self.inside(c, p));
        let inside = match node.op {
            CsgOp::Union | CsgOp::Merge => children.any(|x| x),
            CsgOp::Intersection | CsgOp::Clip => children.all(|x| x),
            CsgOp::Difference => {
                children.next().unwrap_or(false)
                    && node.children[1..]
                        .iter()
                        .zip(children)
                        .all(|(&c, inside)| !inside && self.has_inside(c))
            }
            CsgOp::Bound => children.next().unwrap_or(false),
        };
        inside ^ node.inverse
    }

    /// POV-Ray's bounding test: each bound is met ahead of the ray's origin or holds it.
    fn ray_meets_bounds(&self, bounds: &[u32], ray: &Ray) -> bool {
        bounds.iter().all(|&b| {
            self.item_hit(b, ray, f64::INFINITY, 0).is_some() || self.inside(b, ray.origin)
        })
    }

    /// The materials of the top-level items whose solid holds `p` (for a CSG item, its first
    /// primitive's): where the camera starts, as POV-Ray's interior list does.
    pub fn containing(&self, p: DVec3) -> impl Iterator<Item = u32> + '_ {
        let mut materials = Vec::new();
        for item in self.bvh.item_list().chain(self.unbounded.iter().copied()) {
            match decode(item) {
                Ref::Instance(k) => materials.extend(self.instances[k].containing(p)),
                _ if self.inside(item, p) => materials.extend(self.first_material(item)),
                _ => {}
            }
        }
        materials.into_iter()
    }

    fn first_material(&self, item: u32) -> Option<u32> {
        match decode(item) {
            Ref::Primitive(i) => Some(self.primitives[i].material),
            Ref::Instance(k) => self.instances[k].first_material(),
            Ref::Csg(k) => self.csg[k]
                .children
                .first()
                .and_then(|&c| self.first_material(c)),
        }
    }

    /// The first material of the first top-level item.
    fn top_material(&self) -> Option<u32> {
        let first = self
            .bvh
            .item_list()
            .next()
            .or(self.unbounded.first().copied())?;
        self.first_material(first)
    }

    /// Whether any top-level item's solid holds `p`.
    pub fn holds(&self, p: DVec3) -> bool {
        self.unbounded.iter().any(|&i| self.inside(i, p))
            || self.bvh.any_containing(p, |i| self.inside(i, p))
    }

    /// The nearest hit in (0, t_max), ignoring primitives with any of the `skip` flags.
    pub fn intersect(&self, ray: &Ray, t_max: f64, skip: u8) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut t_best = t_max;
        for &i in &self.unbounded {
            if let Some(hit) = self.item_hit(i, ray, t_best, skip) {
                t_best = hit.t;
                best = Some(hit);
            }
        }
        // An unbounded surface (a plane) wins a tie with a bounded one: POV-Ray renders a
        // glass box resting exactly on a floor plane as if the box were sunk into it (measured:
        // identical to the box lowered by 0.001, unlike raised by 0.001), so the floor is met
        // first from inside the box. The margin is far below any real gap.
        let t_bounded = if best.is_some() {
            t_best * (1.0 - 1e-9)
        } else {
            t_best
        };
        let mut nearest: Option<u32> = None;
        // Once a bounded item is met, one at the very same distance is a tie, settled by
        // the scene's order rather than by the order the tree visits them: items are asked
        // for hits up to just past the nearest one (kept here, not recomputed per item).
        let mut reach = t_bounded;
        self.bvh.traverse(ray, t_bounded, |i, t_cur| {
            match self.item_hit(i, ray, reach, skip) {
                Some(hit)
                    if hit.t < t_cur || nearest.is_some_and(|n| self.declared_before(i, n)) =>
                {
                    best = Some(hit);
                    nearest = Some(i);
                    reach = hit.t.next_up();
                    Some(hit.t)
                }
                _ => Some(t_cur),
            }
        });
        best
    }

    /// Whether top-level item `a` comes before `b` in the scene.
    fn declared_before(&self, a: u32, b: u32) -> bool {
        let place = |item: u32| {
            let k = self.declared.binary_search_by_key(&item, |&(i, _)| i);
            k.map_or(u32::MAX, |k| self.declared[k].1)
        };
        place(a) < place(b)
    }

    /// Whether anything that casts shadows lies on the ray within (0, t_max); stops at the
    /// first hit.
    pub fn occluded(&self, ray: &Ray, t_max: f64) -> bool {
        self.blocker(ray, t_max).is_some()
    }

    /// [`Self::occluded`], testing first the item that stopped the shadow ray before
    /// (`hint`, which it then updates): the shadow rays from one point towards an area
    /// light's grid mostly meet the same object, and one item's test replaces a walk of
    /// the tree. The answer is the same either way.
    pub fn occluded_hinted(&self, ray: &Ray, t_max: f64, hint: &Cell<u32>) -> bool {
        let last = hint.get();
        if last != NO_ITEM && self.item_blocks(last, ray, t_max) {
            return true;
        }
        match self.blocker(ray, t_max) {
            Some(item) => {
                hint.set(item);
                true
            }
            None => false,
        }
    }

    /// The first item found that casts a shadow on the ray within (0, t_max).
    fn blocker(&self, ray: &Ray, t_max: f64) -> Option<u32> {
        if let Some(&i) = self
            .unbounded
            .iter()
            .find(|&&i| self.item_blocks(i, ray, t_max))
        {
            return Some(i);
        }
        let mut hit = None;
        self.bvh.traverse(ray, t_max, |i, t_cur| {
            if self.item_blocks(i, ray, t_cur) {
                hit = Some(i);
                return None;
            }
            Some(t_cur)
        });
        hit
    }

    /// Whether an item casts a shadow on the ray within (0, t_max).
    #[inline(always)]
    fn item_blocks(&self, item: u32, ray: &Ray, t_max: f64) -> bool {
        match decode(item) {
            Ref::Primitive(i) => self
                .primitive_hit(i, ray, t_max, flags::NO_SHADOW)
                .is_some(),
            Ref::Instance(k) => self.instances[k].blocks(ray, t_max),
            Ref::Csg(_) => self
                .composite_hit(item, ray, t_max, flags::NO_SHADOW)
                .is_some(),
        }
    }

    /// Visits every shadow-casting surface crossing on the ray within (0, t_max), in no
    /// particular order, until `visit` returns false (the light is fully blocked). Returns
    /// whether the walk ran to the end. Shadow rays through filtering objects need every
    /// crossing, not only the nearest.
    pub fn shadow_hits(&self, ray: &Ray, t_max: f64, mut visit: impl FnMut(&Hit) -> bool) -> bool {
        self.crossings(ray, t_max, flags::NO_SHADOW, &mut visit)
    }

    /// Visits every surface crossing on the ray within (0, t_max) but those with any of
    /// the `skip` flags, until `visit` returns false; returns whether the walk ran to the
    /// end.
    fn crossings(
        &self,
        ray: &Ray,
        t_max: f64,
        skip: u8,
        visit: &mut dyn FnMut(&Hit) -> bool,
    ) -> bool {
        let mut open = true;
        let everywhere = Cell::new(f64::INFINITY);
        let mut each = |item: u32| {
            self.for_each_hit(item, ray, (0.0, t_max), skip, &everywhere, &mut |hit| {
                if open && !visit(&hit) {
                    open = false;
                }
            });
            open
        };
        for &i in &self.unbounded {
            if !each(i) {
                return false;
            }
        }
        self.bvh.traverse(
            ray,
            t_max,
            |i, t_cur| if each(i) { Some(t_cur) } else { None },
        );
        open
    }

    pub fn primitive_material(&self, primitive: u32) -> u32 {
        self.primitives[primitive as usize].material
    }

    /// The material at a hit: the primitive's, or the face's on a mesh with textures per
    /// face (the first corner's where the corners differ).
    pub fn hit_material(&self, hit: &Hit) -> u32 {
        if let Some(instance) = self.instances.get(hit.instance as usize) {
            return instance.hit_material(hit);
        }
        let p = &self.primitives[hit.primitive as usize];
        match p.shape {
            ShapeKind::Mesh(i) => self.tables.meshes[i as usize]
                .corner_materials(hit.part, p.material)
                .map_or(p.material, |m| m[0]),
            _ => p.material,
        }
    }

    /// The materials mixed at a hit: a mesh face whose corners differ, or a blob with
    /// textured components.
    fn blend(&self, p: &Primitive, part: u32, local: DVec3) -> Option<MaterialBlend> {
        match p.shape {
            ShapeKind::Mesh(i) => {
                let mesh = &self.tables.meshes[i as usize];
                let materials = mesh.corner_materials(part, p.material)?;
                if materials[0] == materials[1] && materials[1] == materials[2] {
                    return None;
                }
                let w = mesh.barycentric(part, local);
                Some(MaterialBlend::Corners {
                    materials,
                    weights: [w.x, w.y, w.z],
                })
            }
            ShapeKind::Blob(i) if self.tables.blobs[i as usize].textured => {
                Some(MaterialBlend::Blob {
                    blob: i,
                    own: p.material,
                    local,
                })
            }
            _ => None,
        }
    }

    /// The materials of a blend and their weights (not normalised).
    pub fn blend_weights(&self, blend: &MaterialBlend) -> impl Iterator<Item = (u32, f64)> + '_ {
        let (corners, blob) = match *blend {
            MaterialBlend::Corners { materials, weights } => {
                (Some(materials.into_iter().zip(weights)), None)
            }
            MaterialBlend::Blob { blob, own, local } => (
                None,
                Some(self.tables.blobs[blob as usize].texture_weights(local, own)),
            ),
        };
        corners
            .into_iter()
            .flatten()
            .chain(blob.into_iter().flatten())
    }

    /// The heaviest material of a blend, whose finish, normal and interior the point uses.
    fn heaviest(&self, blend: &MaterialBlend) -> Option<u32> {
        self.blend_weights(blend)
            .fold(None, |best: Option<(u32, f64)>, (m, w)| {
                if best.is_none_or(|(_, b)| w > b) {
                    Some((m, w))
                } else {
                    best
                }
            })
            .map(|(m, _)| m)
    }

    pub fn surface(&self, ray: &Ray, hit: &Hit) -> SurfacePoint {
        if let Some(instance) = self.instances.get(hit.instance as usize) {
            return instance.surface(ray, hit);
        }
        let p = &self.primitives[hit.primitive as usize];
        let point = ray.at(hit.t);
        let local = self.local_point(p, point);
        let (normal, shading) = p.shape.normals(local, hit.part, &self.tables);
        // Only smooth triangles shade with a normal of their own; the others' is the
        // geometric one, transformed and normalised once.
        let smooth = shading != normal;
        let (normal, shading) = if p.transform == NO_TRANSFORM {
            (normal, shading)
        } else {
            let t = &self.transforms[p.transform as usize];
            (
                t.normal(normal),
                if smooth { t.normal(shading) } else { shading },
            )
        };
        let uv = self.uv(p, hit.part, point);
        let blend = self.blend(p, hit.part, local);
        let material = match &blend {
            Some(b @ MaterialBlend::Blob { .. }) => self.heaviest(b).unwrap_or(p.material),
            _ => self.hit_material(hit),
        };
        let sign = if hit.flipped { -1.0 } else { 1.0 };
        let normal = normal.normalize_or(DVec3::Y) * sign;
        let mut shading_normal = if smooth {
            shading.normalize_or(normal) * sign
        } else {
            normal
        };
        if shading_normal.dot(normal) < 0.0 {
            shading_normal = -shading_normal;
        }
        SurfacePoint {
            point,
            normal,
            shading_normal,
            material,
            uv,
            blend,
        }
    }

    /// The texture lookup point of a hit, without the normals `surface` computes.
    pub fn texture_point(&self, ray: &Ray, hit: &Hit) -> TexturePoint {
        if let Some(instance) = self.instances.get(hit.instance as usize) {
            return instance.texture_point(ray, hit);
        }
        let point = ray.at(hit.t);
        TexturePoint {
            world: point,
            uv: self.uv(&self.primitives[hit.primitive as usize], hit.part, point),
            // Shadow rays skip the normal: a slope pattern reads there as across its
            // direction (a filtering surface textured by slope is the only one to differ).
            normal: DVec3::ZERO,
        }
    }

    /// The primitive's own (u, v) at a world point on it, from its untransformed surface.
    #[inline]
    fn uv(&self, p: &Primitive, part: u32, point: DVec3) -> DVec2 {
        if p.flags & flags::UV == 0 {
            return point.truncate();
        }
        let local = self.local_point(p, point);
        p.shape
            .uv_on(local, part, &self.tables)
            .unwrap_or(point.truncate())
    }

    #[inline]
    fn local_point(&self, p: &Primitive, point: DVec3) -> DVec3 {
        if p.transform == NO_TRANSFORM {
            point
        } else {
            self.transforms[p.transform as usize].inverse_point(point)
        }
    }

    /// The deepest leaf's depth in the BVH (0 for a single leaf or an empty tree).
    pub fn bvh_depth(&self) -> usize {
        self.bvh.depth()
    }

    /// The box around every top-level item, as POV-Ray's `min_extent` and `max_extent`
    /// give it; `None` when an item is unbounded.
    pub fn extent(&self) -> Option<Aabb> {
        if !self.unbounded.is_empty() {
            return None;
        }
        Some(self.bounds())
    }

    pub fn bounds(&self) -> Aabb {
        self.bvh.bounds()
    }
}

#[cfg(test)]
mod tests {
    use super::super::TriangleData;
    use super::*;

    fn sphere_at(b: &mut WorldBuilder, x: f64, r: f64) -> Item {
        b.primitive(
            ShapeKind::Sphere {
                center: DVec3::new(x, 0.0, 0.0),
                radius: r,
            },
            &Transform::IDENTITY,
            0,
            0,
        )
    }

    fn first_hit(world: &World, origin: DVec3, dir: DVec3) -> Option<f64> {
        world
            .intersect(&Ray::new(origin, dir), f64::INFINITY, 0)
            .map(|h| h.t)
    }

    /// A world of primitives drops its tree's item list (the primitives are in leaf
    /// order); each sphere, declared in a scattered order, is still the one a ray aimed at
    /// it meets, and the item list still names every primitive once.
    #[test]
    fn primitives_in_leaf_order_name_themselves() {
        let mut b = WorldBuilder::default();
        for i in 0..200 {
            let x = f64::from((i * 37) % 200) * 3.0;
            let item = sphere_at(&mut b, x, 1.0);
            b.add_top(item);
        }
        let world = b.build();
        assert!(world.bvh.items.is_empty());
        let mut listed: Vec<u32> = world.bvh.item_list().collect();
        listed.sort_unstable();
        assert_eq!(listed, (0..200).collect::<Vec<u32>>());
        for i in 0..200 {
            let x = f64::from(i) * 3.0;
            let hit = world
                .intersect(
                    &Ray::new(DVec3::new(x, 0.0, -5.0), DVec3::Z),
                    f64::INFINITY,
                    0,
                )
                .expect("the sphere in front");
            assert_eq!(hit.t, 4.0);
            let ShapeKind::Sphere { center, .. } = world.primitives[hit.primitive as usize].shape
            else {
                panic!("not a sphere");
            };
            assert_eq!(center.x, x);
        }
    }

    /// A node's box passes every ray the node can stop: 200 turned tiles (a box
    /// and a sphere intersected, or the box less the sphere) in a tree of leaves of
    /// several, rays aimed at points on their boxes' sides, edges and corners and just
    /// outside, answer as the same world with no node's box tested. It fails with the boxes
    /// shrunk by a millionth of their size.
    #[test]
    fn a_nodes_box_passes_every_ray_that_can_cross_the_node() {
        let mut next = crate::geometry::uniform_stream(0x51_7cc1_b727_220a);
        let mut b = WorldBuilder::default();
        for k in 0..200 {
            let c = DVec3::new(next(), next(), next()) * 30.0 - 15.0;
            // Turned by right angles (the box's sides then lie on the node's box's, where
            // the rounding matters) or by any angle.
            let turn = DVec3::new(next(), next(), next()) * 4.0;
            let turn = if k % 3 == 0 {
                turn * 90.0
            } else {
                turn.floor() * 90.0
            };
            let place = Transform::rotate(turn).then(&Transform::translate(c));
            let half = DVec3::new(0.5 + next(), 0.2 + next(), 0.5 + next());
            let cube = b.primitive(
                ShapeKind::Box {
                    min: -half,
                    max: half,
                },
                &place,
                0,
                0,
            );
            let ball = b.primitive(
                ShapeKind::Sphere {
                    center: DVec3::Y * next(),
                    radius: 0.6 + next(),
                },
                &place,
                0,
                0,
            );
            let op = [CsgOp::Intersection, CsgOp::Difference][k % 2];
            let node = b.csg(op, vec![cube, ball], false);
            b.add_top(node);
        }
        let world = b.build();
        assert!(!world.bvh.walks_as_list());
        assert!(world.csg.iter().all(|n| n.own_box.is_some()));
        let mut unboxed = world.clone();
        unboxed.csg.iter_mut().for_each(|n| n.own_box = None);
        let mut met = 0;
        for k in 0..30_000 {
            let node = k % world.csg.len();
            let b = world.csg[node].own_box.expect("bounded").aabb();
            // A point on a side, an edge or a corner of the box, or a hair outside one.
            let mut aim = b.min + (b.max - b.min) * DVec3::new(next(), next(), next());
            for axis in 0..3 {
                if next() < 0.5 {
                    aim[axis] = if next() < 0.5 {
                        b.min[axis]
                    } else {
                        b.max[axis]
                    };
                    aim[axis] += aim[axis].abs() * 1e-7 * (next() - 0.5);
                }
            }
            let origin = DVec3::new(next(), next(), next()) * 80.0 - 40.0;
            // Unnormalised: a shadow query up to t = 1 ends at the aimed point.
            let ray = Ray::new(origin, aim - origin);
            let key = |h: Option<Hit>| h.map(|h| (h.t.to_bits(), h.primitive, h.flipped));
            let hit = key(world.intersect(&ray, f64::INFINITY, 0));
            assert_eq!(
                hit,
                key(unboxed.intersect(&ray, f64::INFINITY, 0)),
                "{ray:?}"
            );
            assert_eq!(
                world.blocker(&ray, 1.0),
                unboxed.blocker(&ray, 1.0),
                "{ray:?}"
            );
            met += usize::from(hit.is_some());
        }
        assert!(met > 5_000, "too few rays met anything ({met})");
    }

    /// A world of spheres and CSG (intersections and differences of boxes and spheres),
    /// for comparing queries that must agree.
    fn csg_cloud() -> (World, impl FnMut() -> f64) {
        let mut next = crate::geometry::uniform_stream(0x9e37_79b9_7f4a_7c15);
        let mut b = WorldBuilder::default();
        for k in 0..60 {
            let c = DVec3::new(next(), next(), next()) * 20.0 - 10.0;
            let ball = b.primitive(
                ShapeKind::Sphere {
                    center: c,
                    radius: 0.5 + next(),
                },
                &Transform::IDENTITY,
                0,
                0,
            );
            let item = if k % 3 == 0 {
                ball
            } else {
                let cube = b.primitive(
                    ShapeKind::Box {
                        min: c - 1.0,
                        max: c + DVec3::new(1.0, 0.6, 1.3),
                    },
                    &Transform::IDENTITY,
                    0,
                    0,
                );
                let op = if k % 3 == 1 {
                    CsgOp::Intersection
                } else {
                    CsgOp::Difference
                };
                b.csg(op, vec![cube, ball], false)
            };
            b.add_top(item);
        }
        (b.build(), next)
    }

    /// The nearest hit, which passes over crossings beyond the nearest found before
    /// testing them against a CSG node's other children, is the nearest of all the
    /// crossings, to the bit.
    #[test]
    fn nearest_hits_are_the_nearest_crossings() {
        let (world, mut next) = csg_cloud();
        let mut met = 0;
        for _ in 0..4000 {
            let origin = DVec3::new(next(), next(), next()) * 30.0 - 15.0;
            let aim = DVec3::new(next(), next(), next()) * 20.0 - 10.0;
            let ray = Ray::new(origin, aim - origin);
            let mut nearest = f64::INFINITY;
            world.crossings(&ray, f64::INFINITY, 0, &mut |hit| {
                nearest = nearest.min(hit.t);
                true
            });
            let hit = world.intersect(&ray, f64::INFINITY, 0).map(|h| h.t);
            assert_eq!(hit, (nearest < f64::INFINITY).then_some(nearest), "{ray:?}");
            met += usize::from(hit.is_some());
        }
        assert!(met > 500, "too few rays met anything ({met})");
    }

    /// Differences and intersections of an isosurface ring (a shape that searches for its
    /// crossings in order, stopping where asked) with spheres. The nearest hit stops the
    /// isosurface's search at the nearest kept crossing; it is the nearest of all the
    /// crossings, to the bit, also where the ray's first crossings of the ring are not
    /// kept (a ray through both sides of the ring, the near one in a subtracted sphere),
    /// and from points on the surfaces (secondary rays); and a shadow query finds a
    /// blocker where there is a crossing. It fails if the search stops at the first
    /// crossing ahead whether kept or not.
    #[test]
    fn an_ordered_search_stops_at_the_nearest_kept_crossing() {
        use crate::function::{Expr, Internal, compile};
        let (major, minor) = (Expr::Const(0.8), Expr::Const(0.35));
        let args = vec![Expr::Arg(0), Expr::Arg(1), Expr::Arg(2), major, minor];
        let function = compile(&Expr::Internal(Internal::Torus, args), 3).expect("compiles");
        let mut b = WorldBuilder::default();
        b.tables.isosurfaces.push(super::super::IsoData {
            function: Arc::new(function),
            container: super::super::Container::Box {
                min: DVec3::splat(-1.2),
                max: DVec3::splat(1.2),
            },
            threshold: 0.0,
            accuracy: 0.001,
            max_gradient: 1.1,
            open: false,
            steepest: Default::default(),
            origin: "test".into(),
        });
        let mut next = crate::geometry::uniform_stream(0x0dd5_ea7c_4e55_1e55);
        let mut centres = Vec::new();
        for k in 0..24 {
            let c = DVec3::new(next(), next(), next()) * 16.0 - 8.0;
            centres.push(c);
            let place = Transform::scale(DVec3::splat(0.8 + next()))
                .expect("invertible")
                .then(&Transform::translate(c));
            let ring = b.primitive(ShapeKind::Isosurface(0), &place, 0, 0);
            let dent = b.primitive(
                ShapeKind::Sphere {
                    center: c + DVec3::new(next(), next(), next()) - 0.5,
                    radius: 0.4 + next(),
                },
                &Transform::IDENTITY,
                0,
                0,
            );
            let node = if k % 2 == 0 {
                b.csg(CsgOp::Difference, vec![ring, dent], false)
            } else {
                b.csg(CsgOp::Intersection, vec![ring, dent], false)
            };
            b.add_top(node);
        }
        let world = b.build();
        let mut met = 0;
        let near_a_ring = |next: &mut dyn FnMut() -> f64| {
            let c = centres[(next() * centres.len() as f64) as usize % centres.len()];
            c + DVec3::new(next(), next(), next()) * 3.0 - 1.5
        };
        for k in 0..3000 {
            let aim = near_a_ring(&mut next);
            let mut origin = DVec3::new(next(), next(), next()) * 30.0 - 15.0;
            if let Some(hit) = world.intersect(&Ray::new(origin, aim - origin), f64::INFINITY, 0) {
                // Every other ray leaves a surface, as reflected and shadow rays do.
                if k % 2 == 0 {
                    origin += (aim - origin) * hit.t;
                }
            }
            let ray = Ray::new(origin, near_a_ring(&mut next) - origin);
            let nearest = nearest_kept(&world, &ray);
            let hit = world.intersect(&ray, f64::INFINITY, 0).map(|h| h.t);
            assert_eq!(hit, (nearest < f64::INFINITY).then_some(nearest), "{ray:?}");
            let near = Ray::new(ray.origin, ray.direction * 3.0);
            let mut crossed = false;
            world.crossings(&near, 1.0, 0, &mut |_| {
                crossed = true;
                false
            });
            assert_eq!(world.blocker(&near, 1.0).is_some(), crossed, "{near:?}");
            met += usize::from(hit.is_some());
        }
        assert!(met > 400, "too few rays met anything ({met})");
    }

    /// The nearest crossing ahead of the ray kept by its node, from every crossing of
    /// every child (the isosurface's searched from the ray's origin on, as the world's
    /// are, so that its roots are the same to the bit).
    fn nearest_kept(world: &World, ray: &Ray) -> f64 {
        let mut best = f64::INFINITY;
        for node in &world.csg {
            for (i, &c) in node.children.iter().enumerate() {
                let Ref::Primitive(j) = decode(c) else {
                    panic!("a node of primitives");
                };
                let p = &world.primitives[j];
                let local = world.local_ray(p, ray);
                let mut keep = |t: f64| {
                    if t > 0.0 && t < best && world.kept(node, i, ray.at(t)) {
                        best = t;
                    }
                };
                match p.shape {
                    ShapeKind::Isosurface(k) => {
                        world.tables.isosurfaces[k as usize].hits_from(&local, 0.0, |t| {
                            keep(t);
                            true
                        });
                    }
                    shape => shape.each_hit(&local, &world.tables, keep),
                }
            }
        }
        best
    }

    /// A quartic clipped by a cylinder and two planes (shapesq.inc's helix), an
    /// intersection of a sphere and a box with it, and the helix as a `poly` clipped the
    /// same way, upright and turned.
    fn clipped_quartics(turn: &Transform) -> (World, [u32; 3]) {
        let mut helix = [0.0; 35];
        (helix[16], helix[18], helix[27], helix[29]) = (-0.1666, 1.0, 0.5, -1.0);
        let mut b = WorldBuilder::default();
        b.tables.quartics.push(helix);
        b.tables
            .polys
            .push(super::super::poly::PolyData::new(4, &helix));
        b.tables
            .quadrics
            .push([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let scale = Transform::scale(DVec3::splat(2.0)).expect("invertible");
        let mut add = |shape, t: &Transform| b.primitive(shape, t, 0, 0);
        let quartic = add(ShapeKind::Quartic(0), turn);
        let cylinder = add(ShapeKind::Quadric(0), &scale.then(turn));
        let plane = |sign: f64, distance| ShapeKind::Plane {
            normal: DVec3::Z * sign,
            distance,
        };
        let (top, bottom) = (
            add(plane(1.0, std::f64::consts::SQRT_2), turn),
            add(plane(-1.0, 0.0), turn),
        );
        let ball = ShapeKind::Sphere {
            center: DVec3::new(0.5, 0.5, 0.7),
            radius: 1.2,
        };
        let cube = ShapeKind::Box {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.2),
        };
        let meet = vec![
            add(ShapeKind::Quartic(0), turn),
            add(ball, turn),
            add(cube, turn),
        ];
        let poly = add(ShapeKind::Poly(0), turn);
        let clip = b.csg(CsgOp::Clip, vec![quartic, cylinder, top, bottom], false);
        let poly = b.csg(CsgOp::Clip, vec![poly, cylinder, top, bottom], false);
        let meet = b.csg(CsgOp::Intersection, meet, false);
        (b.build(), [clip.0, meet.0, poly.0])
    }

    /// The crossings a clip's or an intersection's quartic finds within the window its
    /// convex children leave are those of the whole line that the other children keep;
    /// upright, the clip's box (a cylinder's open sides cut by half-spaces) holds them,
    /// turned it has none (the axes' rounding).
    #[test]
    fn clipped_quartics_search_only_where_the_clip_keeps() {
        let mut found = 0;
        for turn in [
            Transform::IDENTITY,
            Transform::rotate(DVec3::new(20.0, -35.0, 10.0)),
        ] {
            let (world, items) = clipped_quartics(&turn);
            assert!(world.csg.iter().all(|n| n.windowed), "each holds a search");
            let clip = items[0];
            let bounds = world.item_bounds(clip);
            assert_eq!(bounds.is_some(), turn.is_identity());
            let mut next = crate::geometry::uniform_stream(0x1234_5678_9abc_def1);
            let mut v = |s: f64| DVec3::new(next(), next(), next()) * (2.0 * s) - s;
            for _ in 0..3000 {
                let origin = v(6.0);
                let ray = Ray::new(origin, v(1.5) + DVec3::Z * 0.7 - origin);
                for item in items {
                    let hits = windowed_and_kept(&world, item, &ray);
                    for (a, b) in &hits {
                        assert!((a - b).abs() <= 1e-9 * (1.0 + b.abs()), "{ray:?}: {a} {b}");
                        let p = ray.at(*a);
                        let held = |b: &Aabb| p.cmpge(b.min).all() && p.cmple(b.max).all();
                        assert!(item != clip || bounds.is_none_or(|b| held(&b)), "{p}");
                    }
                    found += hits.len();
                }
            }
        }
        assert!(found > 5000, "{found} crossings");
    }

    /// The first child's crossings of a CSG node that `for_each_hit` finds (within its
    /// window), paired with those of the whole line that the other children hold; panics
    /// where their counts differ.
    fn windowed_and_kept(world: &World, item: u32, ray: &Ray) -> Vec<(f64, f64)> {
        let Ref::Csg(k) = decode(item) else {
            unreachable!("a CSG node")
        };
        let children = &world.csg[k].children;
        let Ref::Primitive(first) = decode(children[0]) else {
            unreachable!("a primitive first")
        };
        let mut windowed = Vec::new();
        let everywhere = Cell::new(f64::INFINITY);
        world.for_each_hit(item, ray, (0.0, f64::INFINITY), 0, &everywhere, &mut |h| {
            if h.primitive as usize == first {
                windowed.push(h.t);
            }
        });
        windowed.sort_by(f64::total_cmp);
        let p = &world.primitives[first];
        let whole = p.shape.all_hits(&world.local_ray(p, ray), &world.tables);
        let keeps = |t: f64| children[1..].iter().all(|&c| world.inside(c, ray.at(t)));
        let kept: Vec<f64> = (whole.as_slice().iter().copied())
            .filter(|&t| t > 0.0 && keeps(t))
            .collect();
        assert_eq!(windowed.len(), kept.len(), "{ray:?}: {windowed:?} {kept:?}");
        windowed.into_iter().zip(kept).collect()
    }

    /// A shadow ray that tests first the item that stopped the one before gets the same
    /// answer as a walk of the tree, whatever the hint, and keeps an item that stops it.
    #[test]
    fn hinted_occlusion_agrees_and_keeps_its_blocker() {
        let (world, mut next) = csg_cloud();
        let hint = Cell::new(NO_ITEM);
        let (mut blocked, mut hinted) = (0, 0);
        let target = DVec3::new(3.0, 2.0, 1.0);
        for _ in 0..4000 {
            let origin = DVec3::new(next(), next(), next()) * 30.0 - 15.0;
            let to = target + DVec3::new(next(), next(), next()) * 4.0 - origin;
            let ray = Ray::new(origin, to / to.length());
            let before = hint.get();
            let answer = world.occluded_hinted(&ray, to.length(), &hint);
            assert_eq!(answer, world.occluded(&ray, to.length()), "{ray:?}");
            if answer {
                blocked += 1;
                hinted += usize::from(hint.get() == before);
                assert!(world.item_blocks(hint.get(), &ray, to.length()));
            }
        }
        assert!(
            blocked > 500 && hinted > 50,
            "{blocked} blocked, {hinted} by the hint"
        );
    }

    #[test]
    fn difference_cuts_a_hole() {
        // A unit sphere minus a smaller sphere that pokes out of its front at x = -1.
        let mut b = WorldBuilder::default();
        let a = sphere_at(&mut b, 0.0, 1.0);
        let c = sphere_at(&mut b, -1.0, 0.5);
        let d = b.csg(CsgOp::Difference, vec![a, c], false);
        b.add_top(d);
        let w = b.build();
        // Along the x axis from the left: the small sphere's far side at x = -0.5.
        let t = first_hit(&w, DVec3::new(-5.0, 0.0, 0.0), DVec3::X).unwrap();
        assert!((t - 4.5).abs() < 1e-12, "{t}");
        let hit = w
            .intersect(
                &Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X),
                f64::INFINITY,
                0,
            )
            .unwrap();
        // The cut surface's outward normal points into the hole (towards -x).
        let s = w.surface(&Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X), &hit);
        assert!(s.normal.x < -0.99, "{:?}", s.normal);
        // Away from the hole the big sphere is intact.
        let t = first_hit(&w, DVec3::new(5.0, 0.0, 0.0), -DVec3::X).unwrap();
        assert!((t - 4.0).abs() < 1e-12);
        assert!(w.inside(d.0, DVec3::new(0.5, 0.0, 0.0)));
        assert!(!w.inside(d.0, DVec3::new(-0.8, 0.0, 0.0)));
    }

    #[test]
    fn intersection_and_merge() {
        let mut b = WorldBuilder::default();
        let l = sphere_at(&mut b, -0.5, 1.0);
        let r = sphere_at(&mut b, 0.5, 1.0);
        let lens = b.csg(CsgOp::Intersection, vec![l, r], false);
        b.add_top(lens);
        let w = b.build();
        // The lens spans x in [-0.5, 0.5].
        assert!((first_hit(&w, DVec3::new(-5.0, 0.0, 0.0), DVec3::X).unwrap() - 4.5).abs() < 1e-12);

        let mut b = WorldBuilder::default();
        let l = sphere_at(&mut b, -0.5, 1.0);
        let r = sphere_at(&mut b, 0.5, 1.0);
        let m = b.csg(CsgOp::Merge, vec![l, r], false);
        b.add_top(m);
        let w = b.build();
        // From inside the left sphere towards +x, the merge has no inner wall at x = 0.5 - 1.
        let t = first_hit(&w, DVec3::new(-1.0, 0.0, 0.0), DVec3::X).unwrap();
        assert!((t - 2.5).abs() < 1e-12, "{t}");
    }

    #[test]
    fn a_bound_tests_the_ray_not_the_hit() {
        // A plane x = 2 (unbounded) bounded by a unit sphere at the origin: rays through the
        // sphere see the plane beyond it, rays that pass the sphere see nothing, and a ray
        // starting inside the sphere passes the test too.
        let mut b = WorldBuilder::default();
        let plane = b.primitive(
            ShapeKind::Plane {
                normal: DVec3::X,
                distance: 2.0,
            },
            &Transform::IDENTITY,
            0,
            0,
        );
        let bound = sphere_at(&mut b, 0.0, 1.0);
        let item = b.csg(CsgOp::Bound, vec![plane, bound], false);
        b.add_top(item);
        let w = b.build();
        let t = first_hit(&w, DVec3::new(-5.0, 0.0, 0.0), DVec3::X).unwrap();
        assert!((t - 7.0).abs() < 1e-12, "{t}");
        assert_eq!(first_hit(&w, DVec3::new(-5.0, 1.5, 0.0), DVec3::X), None);
        assert!(first_hit(&w, DVec3::new(0.5, 0.0, 0.0), DVec3::X).is_some());
        assert_eq!(first_hit(&w, DVec3::new(1.5, 0.0, 0.0), DVec3::X), None);
        assert!(w.inside(item.0, DVec3::new(1.5, 5.0, 0.0)));
    }

    #[test]
    fn subtracting_a_surface_without_an_inside_keeps_only_its_part_inside() {
        // A box minus a triangle across it: as in POV-Ray, the box's own faces go and the
        // triangle shows where it is inside the box.
        let mut b = WorldBuilder::default();
        let cube = b.primitive(
            ShapeKind::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::splat(1.0),
            },
            &Transform::IDENTITY,
            0,
            0,
        );
        b.tables.triangles.push(TriangleData {
            p0: DVec3::new(-3.0, 0.0, -3.0),
            e1: DVec3::new(6.0, 0.0, 0.0),
            e2: DVec3::new(0.0, 0.0, 6.0),
            normals: None,
        });
        let tri = b.primitive(ShapeKind::Triangle(0), &Transform::IDENTITY, 0, 0);
        let d = b.csg(CsgOp::Difference, vec![cube, tri], false);
        b.add_top(d);
        let w = b.build();
        let t = first_hit(&w, DVec3::new(-0.5, 5.0, -0.5), -DVec3::Y).unwrap();
        assert!((t - 5.0).abs() < 1e-12, "{t}");
        assert_eq!(first_hit(&w, DVec3::new(-5.0, 0.5, 0.0), DVec3::X), None);
        assert!(!w.inside(d.0, DVec3::new(0.0, 0.5, 0.0)));
    }

    #[test]
    fn coincident_faces_resolve_the_same_way_everywhere() {
        // A box minus a box sharing its top face. Points on a surface count as outside, so
        // the shared face is kept as a skin over the pocket, at every pixel alike.
        let mut b = WorldBuilder::default();
        let outer = b.primitive(
            ShapeKind::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::splat(1.0),
            },
            &Transform::IDENTITY,
            0,
            0,
        );
        let cut = b.primitive(
            ShapeKind::Box {
                min: DVec3::new(-0.5, 0.0, -0.5),
                max: DVec3::new(0.5, 1.0, 0.5),
            },
            &Transform::IDENTITY,
            0,
            0,
        );
        let d = b.csg(CsgOp::Difference, vec![outer, cut], false);
        b.add_top(d);
        let w = b.build();
        let mut ts = Vec::new();
        for i in 0..50 {
            for j in 0..50 {
                let x = -0.45 + 0.9 * i as f64 / 49.0;
                let z = -0.45 + 0.9 * j as f64 / 49.0;
                ts.push(first_hit(&w, DVec3::new(x, 5.0, z), -DVec3::Y).unwrap());
            }
        }
        assert!(ts.iter().all(|&t| (t - 4.0).abs() < 1e-9), "{:?}", &ts[..5]);
    }

    #[test]
    fn permute_moves_each_element_to_its_place() {
        // A permutation with cycles of lengths 1, 2 and 4.
        let dest = [0u32, 2, 1, 4, 5, 6, 3];
        let mut v: Vec<u32> = (0..7).collect();
        permute(&mut v, &mut dest.to_vec());
        for (i, &d) in dest.iter().enumerate() {
            assert_eq!(v[d as usize], i as u32);
        }
    }

    /// A difference of a box and 40 spheres, a merge of 30 spheres (one of them turned
    /// inside out, so unbounded) and a union of both: with the children indexed, every ray
    /// meets the same surfaces and every point is inside the same solids as with the
    /// children scanned one by one.
    #[test]
    fn indexed_children_answer_as_the_scan_does() {
        let build = || {
            let mut b = WorldBuilder::default();
            let slab = b.primitive(
                ShapeKind::Box {
                    min: DVec3::new(-4.0, -0.5, -4.0),
                    max: DVec3::new(4.0, 0.5, 4.0),
                },
                &Transform::IDENTITY,
                0,
                0,
            );
            let mut holes = vec![slab];
            let mut blobs = Vec::new();
            for i in 0..40 {
                let x = -3.5 + (i % 8) as f64;
                let z = -3.5 + (i / 8) as f64 * 1.7;
                holes.push(b.primitive(
                    ShapeKind::Sphere {
                        center: DVec3::new(x, 0.3 * (i % 3) as f64, z),
                        radius: 0.45,
                    },
                    &Transform::IDENTITY,
                    0,
                    0,
                ));
            }
            for i in 0..30 {
                let flags = if i == 7 { flags::INVERSE } else { 0 };
                let c = DVec3::new(-3.0 + 0.2 * i as f64, 1.0, (i as f64).sin());
                let radius = if i == 7 { 9.0 } else { 0.5 };
                let shape = ShapeKind::Sphere { center: c, radius };
                blobs.push(b.primitive(shape, &Transform::IDENTITY, 0, flags));
            }
            let d = b.csg(CsgOp::Difference, holes, false);
            let m = b.csg(CsgOp::Merge, blobs, false);
            let u = b.csg(CsgOp::Union, vec![d, m], false);
            b.add_top(u);
            (b.build(), [d.0, m.0, u.0])
        };
        let (indexed, items) = build();
        let (mut scanned, _) = build();
        assert!(indexed.csg.iter().filter(|n| n.index.is_some()).count() == 2);
        scanned.csg.iter_mut().for_each(|n| n.index = None);
        answers_as_the_scan(&indexed, &scanned, &items, 0x853c_49e6_748f_ea9bu64, |v| {
            v * 6.0
        });
    }

    /// Asserts that 20,000 random rays meet the same surfaces in `indexed` as in `scanned`
    /// (the same world with its children's indexes dropped) and that their origins
    /// (`place` of a point in [-1, 1)^3) are inside the same items, more than 5,000 of the
    /// rays meeting something.
    fn answers_as_the_scan(
        indexed: &World,
        scanned: &World,
        items: &[u32],
        seed: u64,
        place: impl Fn(DVec3) -> DVec3,
    ) {
        let mut uniform = crate::geometry::uniform_stream(seed);
        let mut next = move || uniform() * 2.0 - 1.0;
        let mut hits = 0;
        for _ in 0..20_000 {
            let o = place(DVec3::new(next(), next(), next()));
            let d = DVec3::new(next(), next(), next()).normalize_or(DVec3::Y);
            let ray = Ray::new(o, d);
            let a = indexed
                .intersect(&ray, f64::INFINITY, 0)
                .map(|h| (h.t, h.flipped));
            let b = scanned
                .intersect(&ray, f64::INFINITY, 0)
                .map(|h| (h.t, h.flipped));
            assert_eq!(a, b, "ray {ray:?}");
            hits += usize::from(a.is_some());
            for &item in items {
                assert_eq!(indexed.inside(item, o), scanned.inside(item, o), "{o}");
            }
        }
        assert!(
            hits > 5_000,
            "{hits} hits: the test would not see a difference"
        );
    }

    /// An intersection of turned planes (thingy.inc's pyramid: six planes tilted and
    /// turned about y, an inverted floor) is bounded by its polytope's box and goes into
    /// the tree: it was unbounded, and every ray in the scene tested it (no_image).
    #[test]
    fn an_intersection_of_turned_planes_is_bounded_by_its_polytope() {
        let mut b = WorldBuilder::default();
        let plane = ShapeKind::Plane {
            normal: DVec3::X,
            distance: 0.0,
        };
        // Tilted back by atan(1/2) from the vertical and pushed out by 1: the side of a
        // pyramid of height 2 and apothem 1.
        let tilt = 1f64.atan2(2.0).to_degrees();
        let mut sides: Vec<Item> = (0..6)
            .map(|k| {
                let place = Transform::rotate(DVec3::new(0.0, 0.0, tilt))
                    .then(&Transform::translate(DVec3::X))
                    .then(&Transform::rotate(DVec3::new(
                        0.0,
                        60.0 * f64::from(k),
                        0.0,
                    )));
                b.primitive(plane, &place, 0, 0)
            })
            .collect();
        let floor = ShapeKind::Plane {
            normal: DVec3::Y,
            distance: 0.0,
        };
        sides.push(b.primitive(floor, &Transform::IDENTITY, 0, flags::INVERSE));
        let pyramid = b.csg(CsgOp::Intersection, sides, false);
        b.add_top(pyramid);
        let world = b.build();
        assert!(world.unbounded.is_empty(), "the pyramid is in the tree");
        let extent = world.item_extent(pyramid.0);
        // The base's sides face along x, so its corners lie 2 / sqrt 3 out along z.
        let corner = 2.0 / 3f64.sqrt();
        let expected = Aabb::new(DVec3::new(-1.0, 0.0, -corner), DVec3::new(1.0, 2.0, corner));
        assert!(
            (extent.min - expected.min).abs().max_element() < 1e-9
                && (extent.max - expected.max).abs().max_element() < 1e-9,
            "{extent:?}"
        );
    }

    /// A node of few children is indexed where a ray that meets it mostly misses some of
    /// their boxes and their crossings cost more than the index's box tests (a box less
    /// three small transformed balls in its corners; a union of two apart), not where the
    /// children fill most of the node (a box less two thick slabs through it); indexed,
    /// each answers every ray and point as the scan of its children does.
    #[test]
    fn small_nodes_are_indexed_where_their_children_lie_apart() {
        let build = || {
            let mut b = WorldBuilder::default();
            let cube = |b: &mut WorldBuilder, min: DVec3, max: DVec3| {
                b.primitive(ShapeKind::Box { min, max }, &Transform::IDENTITY, 0, 0)
            };
            let block = cube(&mut b, DVec3::splat(-2.0), DVec3::splat(2.0));
            let mut corners = vec![block];
            for k in 0..3 {
                let c = DVec3::new(
                    [-1.8, 1.8, -1.8][k],
                    [1.8, 1.8, -1.8][k],
                    [1.8, -1.8, -1.8][k],
                );
                let squash = Transform::scale(DVec3::new(0.6, 0.4, 0.5)).unwrap();
                let place = squash.then(&Transform::translate(c));
                let ball = ShapeKind::Sphere {
                    center: DVec3::ZERO,
                    radius: 1.0,
                };
                corners.push(b.primitive(ball, &place, 0, 0));
            }
            let spread = b.csg(CsgOp::Difference, corners, false);
            let slab = |b: &mut WorldBuilder, axis: usize| {
                let (mut min, mut max) = (DVec3::splat(-2.1), DVec3::splat(2.1));
                (min[axis], max[axis]) = (-1.2, 1.2);
                cube(b, min + DVec3::X * 10.0, max + DVec3::X * 10.0)
            };
            let block2 = cube(
                &mut b,
                DVec3::new(8.0, -2.0, -2.0),
                DVec3::new(12.0, 2.0, 2.0),
            );
            let (s1, s2) = (slab(&mut b, 0), slab(&mut b, 1));
            let filled = b.csg(CsgOp::Difference, vec![block2, s1, s2], false);
            let apart = b.csg(CsgOp::Union, vec![spread, filled], false);
            b.add_top(apart);
            (b.build(), [spread.0, filled.0, apart.0])
        };
        let (indexed, items) = build();
        let (mut scanned, _) = build();
        let node = |item: u32| match decode(item) {
            Ref::Csg(k) => &indexed.csg[k],
            _ => unreachable!(),
        };
        assert!(node(items[0]).index.is_some(), "the box less three balls");
        assert!(node(items[1]).index.is_none(), "the box less two slabs");
        assert!(node(items[2]).index.is_some(), "the union of the two");
        scanned.csg.iter_mut().for_each(|n| n.index = None);
        answers_as_the_scan(&indexed, &scanned, &items, 0x94d0_49bb_1331_11ebu64, |v| {
            DVec3::new(5.0 + v.x * 9.0, v.y * 3.0, v.z * 3.0)
        });
    }

    /// Boxes sharing their top face (advanced/pawns' 32 squares set into the board): rays
    /// from above see the one declared first, whichever order the squares and the board are
    /// declared in, wherever the tree puts them.
    #[test]
    fn the_first_declared_of_two_coincident_faces_is_seen() {
        let board = (DVec3::new(-8.0, -0.5, -8.0), DVec3::new(8.0, 0.0, 8.0));
        let squares: Vec<(DVec3, DVec3)> = (0..64)
            .filter(|k| (k % 8 + k / 8) % 2 == 0)
            .map(|k| {
                let (x, z) = (f64::from(k % 8) * 2.0 - 8.0, f64::from(k / 8) * 2.0 - 8.0);
                (DVec3::new(x, -2.0, z), DVec3::new(x + 2.0, 0.0, z + 2.0))
            })
            .collect();
        for board_first in [false, true] {
            let mut b = WorldBuilder::default();
            let add = |b: &mut WorldBuilder, (min, max): (DVec3, DVec3)| {
                let item = b.primitive(ShapeKind::Box { min, max }, &Transform::IDENTITY, 0, 0);
                b.add_top(item);
            };
            if board_first {
                add(&mut b, board);
            }
            squares.iter().for_each(|&s| add(&mut b, s));
            if !board_first {
                add(&mut b, board);
            }
            let w = b.build();
            // The board, under the number the build gave it.
            let rank = if board_first { 0 } else { squares.len() as u32 };
            let board_item = w.declared.iter().find(|d| d.1 == rank).unwrap().0;
            for i in 0..400 {
                let (x, z) = (f64::from(i % 20) * 0.8 - 7.9, f64::from(i / 20) * 0.8 - 7.9);
                let on_square = ((x + 8.0) as i32 / 2 + (z + 8.0) as i32 / 2) % 2 == 0;
                let ray = Ray::new(DVec3::new(x, 5.0, z), -DVec3::Y);
                let hit = w.intersect(&ray, f64::INFINITY, 0).unwrap();
                assert_eq!(hit.t, 5.0);
                let expect_board = board_first || !on_square;
                assert_eq!(
                    hit.primitive == board_item,
                    expect_board,
                    "board first: {board_first}, ray at {x}, {z}"
                );
            }
        }
    }
}
