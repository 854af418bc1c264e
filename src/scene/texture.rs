use glam::DVec3;

use super::{Colour, Transform};

/// A texture as POV-Ray layers it: what colour (pigment), and how light interacts (finish).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Texture {
    pub pigment: Pigment,
    pub finish: Finish,
}

impl Texture {
    pub fn transform_by(&mut self, t: &Transform) {
        self.pigment.transform_by(t);
    }
}

/// Procedural patterns: a function of the point in pattern space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pattern {
    /// Alternates between entry 0 and 1 on unit cubes.
    Checker,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PigmentKind {
    Solid(Colour),
    /// A pattern that picks one of several sub-pigments (checker's two, for instance).
    List {
        pattern: Pattern,
        entries: Vec<Pigment>,
    },
}

/// A pigment with the transform from pattern space to world space.
#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    pub kind: PigmentKind,
    pub transform: Transform,
}

impl Default for Pigment {
    /// POV-Ray's default pigment is black.
    fn default() -> Self {
        Pigment::solid(Colour::BLACK)
    }
}

impl Pigment {
    pub fn solid(c: Colour) -> Pigment {
        Pigment {
            kind: PigmentKind::Solid(c),
            transform: Transform::IDENTITY,
        }
    }

    pub fn transform_by(&mut self, t: &Transform) {
        self.transform = self.transform.then(t);
        if let PigmentKind::List { entries, .. } = &mut self.kind {
            for e in entries {
                e.transform_by(t);
            }
        }
    }
}

/// `reflection { min, max falloff p fresnel exponent e metallic m }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reflection {
    pub min: DVec3,
    pub max: DVec3,
    pub falloff: f64,
    pub fresnel: bool,
    pub exponent: f64,
    pub metallic: f64,
}

impl Default for Reflection {
    fn default() -> Self {
        Reflection {
            min: DVec3::ZERO,
            max: DVec3::ZERO,
            falloff: 1.0,
            fresnel: false,
            exponent: 1.0,
            metallic: 0.0,
        }
    }
}

impl Reflection {
    pub fn is_zero(&self) -> bool {
        self.min == DVec3::ZERO && self.max == DVec3::ZERO
    }
}

/// The finish with POV-Ray's defaults (ambient 0.1, diffuse 0.6, ...).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finish {
    pub ambient: DVec3,
    pub emission: DVec3,
    pub diffuse: f64,
    pub brilliance: f64,
    pub phong: f64,
    pub phong_size: f64,
    pub specular: f64,
    pub roughness: f64,
    pub metallic: f64,
    pub reflection: Reflection,
    pub conserve_energy: bool,
}

impl Default for Finish {
    fn default() -> Self {
        Finish {
            ambient: DVec3::splat(0.1),
            emission: DVec3::ZERO,
            diffuse: 0.6,
            brilliance: 1.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: Reflection::default(),
            conserve_energy: false,
        }
    }
}

/// What is inside a solid object: for now only the index of refraction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interior {
    pub ior: f64,
}

impl Default for Interior {
    fn default() -> Self {
        Interior { ior: 1.0 }
    }
}
