use std::sync::Arc;

use glam::{DVec2, DVec3};

use super::{Interior, SplineKind, Texture, Transform};

/// The shapes a scene can hold, in the scene's own terms (POV-Ray's parameters). CSG
/// shapes own their children.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Sphere {
        center: DVec3,
        radius: f64,
    },
    /// Points p with `normal . p = distance`; the inside is where `normal . p < distance`.
    Plane {
        normal: DVec3,
        distance: f64,
    },
    Box {
        corner1: DVec3,
        corner2: DVec3,
    },
    Cylinder(Box<Cylinder>),
    Cone(Box<Cone>),
    Disc(Box<Disc>),
    /// In the xz plane around the y axis.
    Torus {
        major: f64,
        minor: f64,
    },
    /// `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`:
    /// A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0.
    Quadric(Box<[f64; 10]>),
    /// `quartic { <a0, ..., a34> }`: the general degree-4 polynomial, terms ordered by
    /// descending powers of x, then y, then z (x^4, x^3 y, x^3 z, x^3, x^2 y^2, ...).
    Quartic {
        coefficients: Vec<f64>,
    },
    /// `poly { n, <...> }`, `cubic { <...> }` and `polynomial { n, xyz(i, j, k): c }`: the
    /// polynomial of `order` 2 to 7, coefficients in POV-Ray's `poly` order (as `quartic`'s,
    /// generalised: descending powers of x, then y, then z); the inside is where it is
    /// negative.
    Poly {
        order: u8,
        coefficients: Vec<f64>,
    },
    /// `julia_fractal { ... }`: a 3-D slice of a 4-D Julia set.
    Julia(Box<super::JuliaFractal>),
    /// The corners.
    Triangle(Box<[DVec3; 3]>),
    SmoothTriangle(Box<SmoothTriangle>),
    Mesh(Box<Mesh>),
    /// POV-Ray's polygon: points in one plane; a sub-polygon closes when it repeats its
    /// first point, and sub-polygons combine by the even-odd rule (holes).
    Polygon {
        points: Vec<DVec3>,
    },
    Prism(Box<Prism>),
    Sor(Sor),
    Lathe(Lathe),
    /// One character of a `text` object (which reads as a union of them).
    Glyph(Glyph),
    /// `superellipsoid { <e, n> }`: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in the
    /// unit cube; `east_west` is e, `north_south` is n.
    Superellipsoid {
        east_west: f64,
        north_south: f64,
    },
    Blob(Blob),
    Isosurface(Box<Isosurface>),
    HeightField(Box<HeightField>),
    BicubicPatch(Box<BicubicPatch>),
    Union(Vec<Object>),
    /// A union without the interior surfaces.
    Merge(Vec<Object>),
    Intersection(Vec<Object>),
    /// The first child minus all the others.
    Difference(Vec<Object>),
    /// A declared object of many parts, shared by every `object { Name ... }` that only
    /// moves it: the object holding this shape places it by its own transform (after the
    /// shared object's), and has no texture, interior, flags or clipping of its own (a
    /// modifier other than a transform makes a copy first, see [`Object::unshared`]).
    Instance(Arc<Object>),
}

/// The shapes' parameters too large to sit in [`Shape`] itself: boxed, so a sphere (the
/// shape a scene has millions of) is not the size of the largest shape.
#[derive(Clone, Debug, PartialEq)]
pub struct Cylinder {
    pub base: DVec3,
    pub cap: DVec3,
    pub radius: f64,
    pub open: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Cone {
    pub base: DVec3,
    pub base_radius: f64,
    pub cap: DVec3,
    pub cap_radius: f64,
    pub open: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Disc {
    pub center: DVec3,
    pub normal: DVec3,
    pub radius: f64,
    pub hole_radius: f64,
}

#[derive(Clone, Debug, PartialEq)]
pub struct SmoothTriangle {
    pub corners: [DVec3; 3],
    pub normals: [DVec3; 3],
}

/// `prism { sweep spline height1, height2, n, points }`: closed 2-D shapes in the x-z plane
/// (each point is <x, z>) filled by the even-odd rule and swept along y between the
/// heights. A conic sweep scales the shape by y towards the origin: the points give it at
/// y = 1.
#[derive(Clone, Debug, PartialEq)]
pub struct Prism {
    pub spline: SplineKind,
    pub conic: bool,
    pub height1: f64,
    pub height2: f64,
    pub points: Vec<DVec2>,
    /// Without its caps.
    pub open: bool,
}

/// A glyph's closed curves in a prism's x-z plane, filled by the even-odd rule and swept
/// along y from 0 to `depth`: a prism whose curves come from a font rather than points,
/// so they stay exact (lines and quadratics without rounding into cubics). The object's
/// transform stands it up along z. Glyphs of a font share their curves.
#[derive(Clone, Debug, PartialEq)]
pub struct Glyph {
    pub segments: Arc<[super::Segment]>,
    pub depth: f64,
}

/// `sor { n, <r, h> ... }`: around the y axis, r^2 a cubic spline of the height through
/// the points from the second to the last but one (see `scene::sor_profile`), closed by
/// flat caps unless open.
#[derive(Clone, Debug, PartialEq)]
pub struct Sor {
    pub points: Vec<DVec2>,
    pub open: bool,
}

/// `lathe { spline n, <r, y> ... }`: the spline curve of the points turned around the
/// y axis.
#[derive(Clone, Debug, PartialEq)]
pub struct Lathe {
    pub spline: SplineKind,
    pub points: Vec<DVec2>,
}

/// `mesh` and `mesh2`: faces indexing shared vertex, normal and uv arrays, so a large
/// mesh holds each vertex once.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Mesh {
    pub vertices: Vec<DVec3>,
    pub normals: Vec<DVec3>,
    pub uvs: Vec<DVec2>,
    pub faces: Vec<MeshFace>,
    /// The textures faces name (`texture_list`, a mesh triangle's own); they move with
    /// the mesh.
    pub textures: Vec<Arc<Texture>>,
    /// A direction for the inside test (ray parity); without it a mesh has no inside.
    pub inside_vector: Option<DVec3>,
}

/// `isosurface { function { ... } }`: where the function equals `threshold` inside the
/// container; inside is below the threshold. POV-Ray's defaults: box { -1, 1 },
/// threshold 0, accuracy 0.001, max_gradient 1.1.
#[derive(Clone, Debug, PartialEq)]
pub struct Isosurface {
    pub function: std::sync::Arc<crate::function::Program>,
    pub container: crate::geometry::Container,
    pub threshold: f64,
    pub accuracy: f64,
    pub max_gradient: f64,
    pub open: bool,
    /// file:line:column of the keyword, for warnings after the render.
    pub origin: std::sync::Arc<str>,
}

/// One triangle of a mesh, by index into the mesh's arrays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshFace {
    pub vertices: [u32; 3],
    /// Corner normals (a smooth face).
    pub normals: Option<[u32; 3]>,
    pub uvs: Option<[u32; 3]>,
    /// A texture per corner, into `Mesh::textures` (all three alike for a face texture);
    /// `None` shows the mesh's own texture.
    pub textures: Option<[u32; 3]>,
}

/// `height_field`: heights over the unit square of x and z, y in [0, 1], two triangles per
/// cell of the grid of points.
#[derive(Clone, Debug, PartialEq)]
pub struct HeightField {
    /// Grid points along x and along z.
    pub columns: usize,
    pub rows: usize,
    /// Row by row along x, the first row at z = 0: point (i, j) at x = i / (columns - 1),
    /// z = j / (rows - 1).
    pub heights: Arc<Vec<f32>>,
    /// Normals interpolated across the triangles.
    pub smooth: bool,
    /// Parts below this height are not shown.
    pub water_level: f64,
}

impl HeightField {
    /// Heights from a function of (x, z) in the unit square sampled at the grid points; the
    /// image forms and, later, `height_field { function ... }` both come through here.
    pub fn sample(columns: usize, rows: usize, f: impl Fn(usize, usize) -> f64) -> Vec<f32> {
        let mut heights = Vec::with_capacity(columns * rows);
        for j in 0..rows {
            for i in 0..columns {
                heights.push(f(i, j) as f32);
            }
        }
        heights
    }
}

/// `bicubic_patch`: a Bezier patch of 16 control points (row by row, index 4 v + u).
#[derive(Clone, Debug, PartialEq)]
pub struct BicubicPatch {
    /// POV-Ray's `type`: 0 and 1 render alike in 3.7 (only memory use differs).
    pub kind: u32,
    pub flatness: f64,
    pub u_steps: u32,
    pub v_steps: u32,
    pub points: [DVec3; 16],
    /// The (u, v) of the corners (0,0), (1,0), (1,1), (0,1).
    pub uv: [DVec2; 4],
}

/// POV-Ray's blob: the surface where the summed field of the components equals
/// `threshold`; the inside is where the field exceeds it.
#[derive(Clone, Debug, PartialEq)]
pub struct Blob {
    pub threshold: f64,
    pub components: Vec<BlobComponent>,
}

/// One field source: `strength * (1 - (d / radius)^2)^2` within `radius` of its centre (a
/// point, or a segment whose ends are hemispheres), placed in the blob's space by
/// `transform`.
#[derive(Clone, Debug, PartialEq)]
pub struct BlobComponent {
    pub kind: BlobComponentKind,
    pub radius: f64,
    pub strength: f64,
    pub transform: Transform,
    /// The component's own texture. POV-Ray shows, at a point of the surface, the textures
    /// of the components reaching it mixed by |field| each adds there (measured); a
    /// component without one lends the blob's.
    pub texture: Option<Arc<Texture>>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BlobComponentKind {
    Sphere { center: DVec3 },
    Cylinder { end1: DVec3, end2: DVec3 },
}

impl Shape {
    pub fn children(&self) -> Option<&[Object]> {
        match self {
            Shape::Union(c) | Shape::Merge(c) | Shape::Intersection(c) | Shape::Difference(c) => {
                Some(c)
            }
            _ => None,
        }
    }

    pub fn children_mut(&mut self) -> Option<&mut Vec<Object>> {
        match self {
            Shape::Union(c) | Shape::Merge(c) | Shape::Intersection(c) | Shape::Difference(c) => {
                Some(c)
            }
            _ => None,
        }
    }
}

/// Membership of a `light_group { }`: the objects in it are lit only by the group's own
/// lights, and also by the global lights (those in no group) with `global_lights on`.
/// Shadows ignore groups: every object shadows every light (measured with POV-Ray 3.7).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightGroup {
    pub id: u32,
    pub global_lights: bool,
}

impl LightGroup {
    /// Whether a light of group `light` (`None`: global) lights an object of group `object`.
    pub fn lights(light: Option<u32>, object: Option<LightGroup>) -> bool {
        match (light, object) {
            (None, None) => true,
            (None, Some(g)) => g.global_lights,
            (Some(l), Some(g)) => l == g.id,
            (Some(_), None) => false,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ObjectFlags {
    pub no_shadow: bool,
    pub no_image: bool,
    pub no_reflection: bool,
    pub hollow: bool,
    pub inverse: bool,
    pub double_illuminate: bool,
    /// The innermost `light_group` the object is in.
    pub light_group: Option<LightGroup>,
    /// Unseen by radiosity rays (they pass through it); still lit by radiosity itself.
    pub no_radiosity: bool,
    /// The innermost `photons { }` block.
    pub photons: Option<super::ObjectPhotons>,
}

/// A shape with its placement and appearance. `transform` maps the shape's own coordinates
/// to world space; a child of a CSG shape carries its full transform to world space too.
/// `texture: None` means "inherit from the enclosing CSG, else the default texture".
/// Textures are shared (`Arc`): the objects a loop makes with the same texture hold one copy,
/// and changing one (a transform) copies it first.
///
/// What most objects lack is boxed and absent (a transform, an interior, clipping), so a
/// sphere of a million-sphere loop costs little more than its shape (see the size test).
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    pub shape: Shape,
    pub transform: Placement,
    pub texture: Option<Arc<Texture>>,
    /// `interior_texture { }`: the texture on the surface's inner side, where a ray meets
    /// it going along its outward normal (`None`: inherited, else the texture).
    pub interior_texture: Option<Arc<Texture>>,
    pub interior: Option<Box<Interior>>,
    pub flags: ObjectFlags,
    pub clipping: Option<Box<Clipping>>,
}

/// An object's transform, absent when it is the identity; reads (and prints) as a
/// [`Transform`].
#[derive(Clone, PartialEq, Default)]
pub struct Placement(Option<Box<Transform>>);

impl std::fmt::Debug for Placement {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        (**self).fmt(f)
    }
}

impl Placement {
    pub fn new(t: Transform) -> Placement {
        Placement((!t.is_identity()).then(|| Box::new(t)))
    }
}

impl std::ops::Deref for Placement {
    type Target = Transform;
    fn deref(&self) -> &Transform {
        self.0.as_deref().unwrap_or(&Transform::IDENTITY)
    }
}

/// The objects that cut an object down or bound it.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Clipping {
    /// `clipped_by { ... }`: only the parts of the surface inside all of these remain.
    pub clipped_by: Vec<Object>,
    /// `bounded_by { ... }` where POV-Ray honours it: a ray that meets none of these (and
    /// does not start inside them) misses the object, wherever the surface lies.
    pub bounded_by: Vec<Object>,
}

/// A declared CSG object with at least this many objects in it, or a mesh with this many
/// triangles, is shared by the objects that place it rather than copied into each (see
/// [`Shape::Instance`]): below it, an instance's own materials and transform cost more
/// than the copy.
pub const SHARED_PARTS: usize = 32;

impl Object {
    /// The object as a declaration keeps it: behind a shared pointer when it is a mesh or
    /// a CSG object of [`SHARED_PARTS`] parts or more and holds no instance itself (the
    /// render-ready scene places prototypes, not instances of instances).
    pub fn shared_if_large(self) -> Object {
        let large = match &self.shape {
            Shape::Mesh(m) => m.faces.len() >= SHARED_PARTS,
            shape => shape.children().is_some() && self.parts().is_some_and(|n| n >= SHARED_PARTS),
        };
        if !large {
            return self;
        }
        Object::new(Shape::Instance(Arc::new(self)))
    }

    /// The shape an instance shares, or the object's own.
    pub fn own_shape(&self) -> &Shape {
        match &self.shape {
            Shape::Instance(shared) => &shared.shape,
            shape => shape,
        }
    }

    /// The objects in this one's CSG tree, itself included; `None` if it holds an
    /// instance.
    fn parts(&self) -> Option<usize> {
        match &self.shape {
            Shape::Instance(_) => None,
            shape => shape
                .children()
                .unwrap_or(&[])
                .iter()
                .try_fold(1, |n, c| Some(n + c.parts()?)),
        }
    }

    /// The object with an instance replaced by its own copy of the shared object, moved
    /// into place, so it can take modifiers of its own; other objects as they are.
    pub fn unshared(&mut self) {
        if let Shape::Instance(shared) = &self.shape {
            let mut copy = (**shared).clone();
            copy.transform_by(&self.transform);
            *self = copy;
        }
    }

    pub fn new(shape: Shape) -> Object {
        Object {
            shape,
            transform: Placement::default(),
            texture: None,
            interior_texture: None,
            interior: None,
            flags: ObjectFlags::default(),
            clipping: None,
        }
    }

    /// Applies a world-space transform after everything already applied: to the shape,
    /// to the texture attached so far, to every CSG child (whose transforms are also in
    /// world space) and to the clipping objects. A texture attached later is not moved, as
    /// in POV-Ray.
    pub fn transform_by(&mut self, t: &Transform) {
        self.transform = Placement::new(self.transform.then(t));
        if let Some(texture) = &mut self.texture {
            Arc::make_mut(texture).transform_by(t);
        }
        if let Some(texture) = &mut self.interior_texture {
            Arc::make_mut(texture).transform_by(t);
        }
        if let Some(interior) = &mut self.interior {
            interior.transform_by(t);
        }
        match &mut self.shape {
            Shape::Mesh(mesh) => {
                for texture in &mut mesh.textures {
                    Arc::make_mut(texture).transform_by(t);
                }
            }
            Shape::Blob(blob) => {
                for texture in blob
                    .components
                    .iter_mut()
                    .filter_map(|c| c.texture.as_mut())
                {
                    Arc::make_mut(texture).transform_by(t);
                }
            }
            _ => {}
        }
        if let Some(children) = self.shape.children_mut() {
            for child in children {
                child.transform_by(t);
            }
        }
        if let Some(c) = &mut self.clipping {
            for clip in c.clipped_by.iter_mut().chain(&mut c.bounded_by) {
                clip.transform_by(t);
            }
        }
    }

    pub fn clipped_by(&self) -> &[Object] {
        self.clipping.as_ref().map_or(&[], |c| &c.clipped_by)
    }

    pub fn bounded_by(&self) -> &[Object] {
        self.clipping.as_ref().map_or(&[], |c| &c.bounded_by)
    }

    /// The clipping objects, made on first use.
    pub fn clipping_mut(&mut self) -> &mut Clipping {
        self.clipping.get_or_insert_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A large scene is millions of simple objects: the model must stay small per object
    /// (issue 16's memory goal is 200 bytes per sphere in the whole process). A shape or
    /// object field that grows past these fails here rather than in a memory benchmark.
    #[test]
    fn a_simple_object_stays_small() {
        println!(
            "Shape {} B, Object {} B, ObjectFlags {} B",
            size_of::<Shape>(),
            size_of::<Object>(),
            size_of::<ObjectFlags>()
        );
        assert!(
            size_of::<Shape>() <= 56,
            "Shape is {} B",
            size_of::<Shape>()
        );
        assert!(
            size_of::<Object>() <= 128,
            "Object is {} B",
            size_of::<Object>()
        );
    }
}
