//! The functions that ask an object about its geometry while the scene is read: `trace`,
//! `min_extent`, `max_extent` and `inside`. They build the object the way the renderer
//! does (a one-object prepared scene), so what a scene places on a surface lies on the
//! surface penumbra renders; scenes ask the same object many times (`trace` in a loop), so
//! the last few builds are kept, found again by comparing the objects.

use std::rc::Rc;

use glam::DVec3;

use super::super::diagnostics::{Diagnostic, Span};
use super::Evaluator;
use super::functions::Call;
use super::value::{Value, Vector};
use crate::geometry::Ray;
use crate::render::prepared::PreparedScene;
use crate::scene::{Object, Scene};

type R<T> = Result<T, Diagnostic>;

/// How many built objects are kept.
const CACHED: usize = 4;

/// What POV-Ray's extents give for an unbounded object (measured: a plane's
/// `max_extent` is <1e10, 1e10, 1e10>).
const HUGE_EXTENT: f64 = 1e10;

/// The objects asked about, built, most recent last.
#[derive(Default)]
pub struct Placements {
    built: Vec<(Object, Rc<PreparedScene>)>,
}

impl Placements {
    fn get(&mut self, object: &Object) -> Rc<PreparedScene> {
        if let Some(i) = self.built.iter().position(|(o, _)| o == object) {
            let entry = self.built.remove(i);
            let scene = entry.1.clone();
            self.built.push(entry);
            return scene;
        }
        let scene = Scene {
            objects: vec![object.clone()],
            ..Scene::default()
        };
        let prepared = Rc::new(PreparedScene::new(&scene));
        if self.built.len() == CACHED {
            self.built.remove(0);
        }
        self.built.push((object.clone(), prepared.clone()));
        prepared
    }
}

fn vector(v: DVec3) -> Value {
    Value::Vector(Vector::new3(v))
}

impl Evaluator<'_> {
    /// The built form of the call's object argument `i`.
    fn placed(&mut self, call: &Call<'_>, i: usize) -> R<Option<Rc<PreparedScene>>> {
        let (value, span) = &call.args[i];
        match value {
            Value::Object(o) => Ok(o.object.as_ref().map(|o| self.placements.get(o))),
            other => Err(self.err(
                *span,
                format!(
                    "`{}` needs an object as its first argument, found {}",
                    call.name,
                    other.kind_name()
                ),
            )),
        }
    }

    fn vector_arg(&self, call: &Call<'_>, i: usize) -> R<DVec3> {
        let (v, s) = &call.args[i];
        self.to_vec3(v, *s)
    }

    /// The box `min_extent` and `max_extent` report: POV-Ray's huge one for unbounded
    /// objects, zeros for an empty one.
    fn extent(&mut self, call: &Call<'_>) -> R<(DVec3, DVec3)> {
        let Some(scene) = self.placed(call, 0)? else {
            return Ok((DVec3::ZERO, DVec3::ZERO));
        };
        Ok(match scene.world.extent() {
            None => (DVec3::splat(-HUGE_EXTENT), DVec3::splat(HUGE_EXTENT)),
            Some(b) if b.is_empty() => (DVec3::ZERO, DVec3::ZERO),
            Some(b) => (
                b.min
                    .clamp(DVec3::splat(-HUGE_EXTENT), DVec3::splat(HUGE_EXTENT)),
                b.max
                    .clamp(DVec3::splat(-HUGE_EXTENT), DVec3::splat(HUGE_EXTENT)),
            ),
        })
    }

    /// Where `trace`'s optional fourth argument, a variable's name, gets the normal.
    fn set_normal(&mut self, call: &Call<'_>, normal: DVec3) {
        if let Some((Value::Str(name), _)) = call.args.get(3) {
            self.assign(name, vector(normal), false);
        }
    }
}

/// `trace(object, start, direction [, normal])`: the first hit ahead of `start`, and the
/// surface's outward normal there (unit); on a miss <0, 0, 0> for both, as POV-Ray gives.
pub(super) fn trace(ev: &mut Evaluator<'_>, call: &Call<'_>) -> R<Value> {
    let scene = ev.placed(call, 0)?;
    let start = ev.vector_arg(call, 1)?;
    let direction = ev.vector_arg(call, 2)?;
    let ray = Ray::new(start, direction);
    let hit = scene
        .as_ref()
        .filter(|_| direction != DVec3::ZERO)
        .and_then(|s| {
            let hit = s.world.intersect(&ray, f64::INFINITY, 0)?;
            let surface = s.world.surface(&ray, &hit);
            Some((surface.point, surface.normal))
        });
    let (point, normal) = hit.unwrap_or((DVec3::ZERO, DVec3::ZERO));
    ev.set_normal(call, normal);
    Ok(vector(point))
}

pub(super) fn min_extent(ev: &mut Evaluator<'_>, call: &Call<'_>) -> R<Value> {
    Ok(vector(ev.extent(call)?.0))
}

pub(super) fn max_extent(ev: &mut Evaluator<'_>, call: &Call<'_>) -> R<Value> {
    Ok(vector(ev.extent(call)?.1))
}

/// `inside(object, point)`: 1 where the point is inside the object's solid, else 0.
pub(super) fn inside(ev: &mut Evaluator<'_>, call: &Call<'_>) -> R<Value> {
    let scene = ev.placed(call, 0)?;
    let p = ev.vector_arg(call, 1)?;
    let inside = scene.is_some_and(|s| s.world.containing(p).next().is_some());
    Ok(Value::Float(f64::from(u8::from(inside))))
}

/// Reads `trace`'s fourth argument: the name of the variable that receives the normal,
/// carried to the call as a string. It must exist already, as POV-Ray requires ("Expected
/// ')', undeclared identifier found instead").
pub(super) fn normal_name(ev: &mut Evaluator<'_>) -> R<(Value, Span)> {
    let tok = ev.next()?;
    match tok.ident() {
        Some(name) if ev.lookup(name).is_some() => Ok((Value::Str(Rc::from(name)), tok.span)),
        Some(name) => Err(ev.err(
            tok.span,
            format!("trace's normal variable `{name}` must be declared before the call"),
        )),
        None => Err(ev.expected("a variable name to receive trace's normal", &tok)),
    }
}
