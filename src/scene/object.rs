use glam::DVec3;

use super::{Interior, Texture, Transform};

/// The shapes a scene can hold. CSG shapes own their children.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Sphere { center: DVec3, radius: f64 },
    /// Points p with `normal . p = distance`; the inside is where `normal . p < distance`.
    Plane { normal: DVec3, distance: f64 },
    Box { corner1: DVec3, corner2: DVec3 },
    Union(Vec<Object>),
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
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    pub shape: Shape,
    pub transform: Transform,
    pub texture: Option<Texture>,
    pub interior: Option<Interior>,
    pub flags: ObjectFlags,
}

impl Object {
    pub fn new(shape: Shape) -> Object {
        Object {
            shape,
            transform: Transform::IDENTITY,
            texture: None,
            interior: None,
            flags: ObjectFlags::default(),
        }
    }

    /// Applies a world-space transform after everything already applied: to the shape,
    /// to the texture attached so far, and to every CSG child (whose transforms are also in
    /// world space). A texture attached later is not moved, as in POV-Ray.
    pub fn transform_by(&mut self, t: &Transform) {
        self.transform = self.transform.then(t);
        if let Some(texture) = &mut self.texture {
            texture.transform_by(t);
        }
        if let Shape::Union(children) = &mut self.shape {
            for child in children {
                child.transform_by(t);
            }
        }
    }
}
