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
    Cylinder {
        base: DVec3,
        cap: DVec3,
        radius: f64,
        open: bool,
    },
    Cone {
        base: DVec3,
        base_radius: f64,
        cap: DVec3,
        cap_radius: f64,
        open: bool,
    },
    Disc {
        center: DVec3,
        normal: DVec3,
        radius: f64,
        hole_radius: f64,
    },
    /// In the xz plane around the y axis.
    Torus {
        major: f64,
        minor: f64,
    },
    /// `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`:
    /// A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0.
    Quadric {
        coefficients: [f64; 10],
    },
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
    Julia(super::JuliaFractal),
    Triangle {
        corners: [DVec3; 3],
    },
    SmoothTriangle {
        corners: [DVec3; 3],
        normals: [DVec3; 3],
    },
    Mesh(Mesh),
    /// POV-Ray's polygon: points in one plane; a sub-polygon closes when it repeats its
    /// first point, and sub-polygons combine by the even-odd rule (holes).
    Polygon {
        points: Vec<DVec3>,
    },
    Prism(Prism),
    Sor(Sor),
    Lathe(Lathe),
    /// `superellipsoid { <e, n> }`: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in the
    /// unit cube; `east_west` is e, `north_south` is n.
    Superellipsoid {
        east_west: f64,
        north_south: f64,
    },
    Blob(Blob),
    Union(Vec<Object>),
    /// A union without the interior surfaces.
    Merge(Vec<Object>),
    Intersection(Vec<Object>),
    /// The first child minus all the others.
    Difference(Vec<Object>),
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

#[derive(Clone, Debug, PartialEq, Default)]
pub struct Mesh {
    pub triangles: Vec<MeshTriangle>,
    /// A direction for the inside test (ray parity); without it a mesh has no inside.
    pub inside_vector: Option<DVec3>,
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
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BlobComponentKind {
    Sphere { center: DVec3 },
    Cylinder { end1: DVec3, end2: DVec3 },
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshTriangle {
    pub corners: [DVec3; 3],
    pub normals: Option<[DVec3; 3]>,
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

#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct ObjectFlags {
    pub no_shadow: bool,
    pub no_image: bool,
    pub no_reflection: bool,
    pub hollow: bool,
    pub inverse: bool,
    pub double_illuminate: bool,
}

/// A shape with its placement and appearance. `transform` maps the shape's own coordinates
/// to world space; a child of a CSG shape carries its full transform to world space too.
/// `texture: None` means "inherit from the enclosing CSG, else the default texture".
/// Textures are shared (`Arc`): the objects a loop makes with the same texture hold one copy,
/// and changing one (a transform) copies it first.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    pub shape: Shape,
    pub transform: Transform,
    pub texture: Option<Arc<Texture>>,
    pub interior: Option<Interior>,
    pub flags: ObjectFlags,
    /// `clipped_by { ... }`: only the parts of the surface inside all of these remain.
    pub clipped_by: Vec<Object>,
    /// `bounded_by { ... }` where POV-Ray honours it: a ray that meets none of these (and
    /// does not start inside them) misses the object, wherever the surface lies.
    pub bounded_by: Vec<Object>,
}

impl Object {
    pub fn new(shape: Shape) -> Object {
        Object {
            shape,
            transform: Transform::IDENTITY,
            texture: None,
            interior: None,
            flags: ObjectFlags::default(),
            clipped_by: Vec::new(),
            bounded_by: Vec::new(),
        }
    }

    /// Applies a world-space transform after everything already applied: to the shape,
    /// to the texture attached so far, to every CSG child (whose transforms are also in
    /// world space) and to the clipping objects. A texture attached later is not moved, as
    /// in POV-Ray.
    pub fn transform_by(&mut self, t: &Transform) {
        self.transform = self.transform.then(t);
        if let Some(texture) = &mut self.texture {
            Arc::make_mut(texture).transform_by(t);
        }
        if let Some(interior) = &mut self.interior {
            interior.transform_by(t);
        }
        if let Some(children) = self.shape.children_mut() {
            for child in children {
                child.transform_by(t);
            }
        }
        for clip in self.clipped_by.iter_mut().chain(&mut self.bounded_by) {
            clip.transform_by(t);
        }
    }
}
