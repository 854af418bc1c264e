//! The values an identifier can hold. Arithmetic lives here, span-free; the evaluator
//! attaches the span of the operator when an operation fails.

use std::rc::Rc;

use glam::DVec3;

use crate::scene::{
    CameraSpec, Colour, Finish, Interior, Light, Object, Pigment, Texture, Transform,
};

use super::super::syntax::Token;

/// Vectors of 2 to 5 components and colours share one representation, because POV-Ray lets
/// them mix in arithmetic (a colour is a 5-vector: r, g, b, filter, transmit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vector {
    pub c: [f64; 5],
    pub len: u8,
}

impl Vector {
    pub fn new3(v: DVec3) -> Vector {
        Vector {
            c: [v.x, v.y, v.z, 0.0, 0.0],
            len: 3,
        }
    }

    pub fn xyz(&self) -> DVec3 {
        DVec3::new(self.c[0], self.c[1], self.c[2])
    }
}

/// An object as the evaluator carries it: light sources may sit inside CSG and must move
/// with it, so they travel beside the shape until the object reaches the scene.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ObjectValue {
    pub object: Option<Object>,
    pub lights: Vec<Light>,
}

impl ObjectValue {
    pub fn transform_by(&mut self, t: &Transform) {
        if let Some(o) = &mut self.object {
            o.transform_by(t);
        }
        for l in &mut self.lights {
            transform_light(l, t);
        }
    }
}

pub fn transform_light(l: &mut Light, t: &Transform) {
    l.location = t.point(l.location);
    match &mut l.kind {
        crate::scene::LightKind::Point => {}
        crate::scene::LightKind::Spot { point_at, .. }
        | crate::scene::LightKind::Cylinder { point_at, .. }
        | crate::scene::LightKind::Parallel { point_at } => *point_at = t.point(*point_at),
    }
    if let Some(o) = &mut l.looks_like {
        o.transform_by(t);
    }
    if let Some(a) = &mut l.area {
        a.axis1 = t.vector(a.axis1);
        a.axis2 = t.vector(a.axis2);
    }
}

#[derive(Clone, Debug)]
pub struct MacroDef {
    pub name: super::super::syntax::Name,
    pub params: Vec<(super::super::syntax::Name, bool)>,
    pub tokens: Rc<[Token]>,
    /// Token indices of the body: from after the parameter list to the closing `#end`.
    pub start: usize,
    pub end: usize,
    pub file: super::super::diagnostics::FileId,
}

#[derive(Clone, Debug)]
pub enum Value {
    Float(f64),
    Vector(Vector),
    Colour([f64; 5]),
    Str(Rc<str>),
    Object(Box<ObjectValue>),
    Camera(Box<CameraSpec>),
    Pigment(Box<Pigment>),
    Finish(Box<Finish>),
    /// A declared `normal { }` (None: one that perturbs nothing).
    Normal(Box<Option<crate::scene::Normal>>),
    Texture(Box<Texture>),
    Interior(Box<Interior>),
    /// A `material`: the texture and interior it sets, if any.
    Material(Box<(Option<Texture>, Option<Interior>)>),
    Transform(Box<Transform>),
    Macro(Rc<MacroDef>),
    SkySphere(Box<crate::scene::SkySphere>),
    Fog(Box<crate::scene::Fog>),
    Media(Box<crate::scene::Media>),
    Array(Rc<std::cell::RefCell<ArrayValue>>),
    Function(Rc<crate::function::Function>),
    Spline(Rc<crate::scene::path_spline::PathSpline>),
    /// A declaration that used a feature penumbra lacks. Include files declare many things
    /// a scene never uses, so the error waits until the identifier is used.
    Unsupported(Rc<super::super::diagnostics::Diagnostic>),
}

#[derive(Clone, Debug)]
pub struct ArrayValue {
    pub dims: Vec<usize>,
    pub items: Vec<Option<Value>>,
}

impl Value {
    /// Macros and unsupported values act where their names appear in the token stream.
    pub fn needs_check_in_stream(&self) -> bool {
        matches!(self, Value::Macro(_) | Value::Unsupported(_))
    }

    pub fn kind_name(&self) -> &'static str {
        match self {
            Value::Float(_) => "a float",
            Value::Vector(_) => "a vector",
            Value::Colour(_) => "a colour",
            Value::Str(_) => "a string",
            Value::Object(_) => "an object",
            Value::Camera(_) => "a camera",
            Value::Pigment(_) => "a pigment",
            Value::Finish(_) => "a finish",
            Value::Texture(_) => "a texture",
            Value::Interior(_) => "an interior",
            Value::Material(_) => "a material",
            Value::Transform(_) => "a transform",
            Value::Macro(_) => "a macro",
            Value::SkySphere(_) => "a sky_sphere",
            Value::Fog(_) => "a fog",
            Value::Media(_) => "a media",
            Value::Array(_) => "an array",
            Value::Function(_) => "a function",
            Value::Normal(_) => "a normal",
            Value::Spline(_) => "a spline",
            Value::Unsupported(_) => "an unsupported value",
        }
    }
}

pub fn colour_of(c: [f64; 5]) -> Colour {
    Colour {
        rgb: DVec3::new(c[0], c[1], c[2]),
        filter: c[3],
        transmit: c[4],
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
}

/// Float, vector and colour arithmetic with POV-Ray's promotion: a float applies to every
/// component, a shorter vector is padded with zeros, and anything mixed with a colour is a
/// colour. `Err` carries the message.
pub fn arith(op: BinOp, a: &Value, b: &Value) -> Result<Value, String> {
    let apply = |x: f64, y: f64| -> Result<f64, String> {
        Ok(match op {
            BinOp::Add => x + y,
            BinOp::Sub => x - y,
            BinOp::Mul => x * y,
            BinOp::Div => {
                if y == 0.0 {
                    return Err("division by zero".into());
                }
                x / y
            }
        })
    };
    match (a, b) {
        (Value::Float(x), Value::Float(y)) => Ok(Value::Float(apply(*x, *y)?)),
        _ => {
            let (ca, la, cola) = components(a)?;
            let (cb, lb, colb) = components(b)?;
            let colour = cola || colb;
            let len = if colour {
                5
            } else {
                la.unwrap_or(0).max(lb.unwrap_or(0)).max(2)
            };
            let mut out = [0.0; 5];
            for i in 0..len {
                // A shorter operand (not a float, which was splatted) reads as zero beyond its
                // length; dividing by such a padding zero is not an error in POV-Ray's spirit
                // of "unused component", so keep the numerator.
                let y = cb[i];
                out[i] = if op == BinOp::Div && y == 0.0 && lb.is_some_and(|lb| i >= lb) {
                    ca[i]
                } else {
                    apply(ca[i], y)?
                };
            }
            Ok(if colour {
                Value::Colour(out)
            } else {
                Value::Vector(Vector {
                    c: out,
                    len: len as u8,
                })
            })
        }
    }
}

/// Components, length and whether it is a colour; floats fill every component.
fn components(v: &Value) -> Result<([f64; 5], Option<usize>, bool), String> {
    match v {
        Value::Float(f) => Ok(([*f; 5], None, false)),
        Value::Vector(v) => Ok((v.c, Some(v.len as usize), false)),
        Value::Colour(c) => Ok((*c, Some(5), true)),
        other => Err(format!("cannot do arithmetic on {}", other.kind_name())),
    }
}

pub fn negate(v: &Value) -> Result<Value, String> {
    arith(BinOp::Mul, v, &Value::Float(-1.0))
}
