//! `isosurface { function { ... } contained_by { box | sphere } threshold accuracy
//! max_gradient evaluate open max_trace all_intersections }`.

use super::super::diagnostics::{Diagnostic, Span};
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::{ObjectValue, Value};
use crate::geometry::Container;
use crate::scene::{Isosurface, Object, Shape};
use glam::DVec3;

type R<T> = Result<T, Diagnostic>;

impl Evaluator<'_> {
    /// The isosurface's own items, up to its object modifiers.
    pub(super) fn isosurface_items(&mut self, kw: &Token) -> R<ObjectValue> {
        let first = self.peek()?;
        let function = match first.ident() {
            Some("function") => {
                self.next()?;
                self.point_function(first.span)?
            }
            _ => {
                return Err(self.expected(
                    "`function { ... }` (it must come first in an isosurface)",
                    &first,
                ));
            }
        };
        let mut iso = Isosurface {
            function,
            container: Container::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::splat(1.0),
            },
            threshold: 0.0,
            accuracy: 0.001,
            max_gradient: 1.1,
            open: false,
            origin: self.files.locate(kw.span).map_or_else(
                || "isosurface".into(),
                |l| format!("{}:{}:{}", l.file, l.line, l.column).into(),
            ),
        };
        while self.isosurface_item(&mut iso)? {}
        self.check_isosurface(&iso, kw.span)?;
        Ok(ObjectValue {
            object: Some(Object::new(Shape::Isosurface(Box::new(iso)))),
            ..ObjectValue::default()
        })
    }

    /// One item; false at the first token that is not one.
    fn isosurface_item(&mut self, iso: &mut Isosurface) -> R<bool> {
        let tok = self.peek()?;
        match tok.ident() {
            Some("contained_by") => {
                self.next()?;
                iso.container = self.container()?;
            }
            Some("threshold") => {
                self.next()?;
                iso.threshold = self.float()?;
            }
            Some("accuracy") => {
                self.next()?;
                iso.accuracy = self.float()?;
            }
            Some("max_gradient") => {
                self.next()?;
                iso.max_gradient = self.float()?;
            }
            // POV-Ray adapts the gradient during the render from P0 up, by factor P1; a fixed
            // P0 * P1 keeps the image independent of the order pixels are traced in.
            Some("evaluate") => {
                self.next()?;
                let p0 = self.float()?;
                self.eat(Punct::Comma)?;
                let p1 = self.float()?;
                self.eat(Punct::Comma)?;
                self.float()?;
                iso.max_gradient = p0 * p1.max(1.0);
            }
            Some("open") => {
                self.next()?;
                iso.open = self.optional_bool()?;
            }
            // Every crossing is found anyway (CSG needs them), so these change nothing.
            Some("max_trace") => {
                self.next()?;
                self.float()?;
            }
            Some("all_intersections") => {
                self.next()?;
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    fn check_isosurface(&self, iso: &Isosurface, span: Span) -> R<()> {
        if !(iso.accuracy > 0.0 && iso.accuracy.is_finite()) {
            return Err(self.err(
                span,
                format!(
                    "the isosurface's accuracy {} must be positive",
                    iso.accuracy
                ),
            ));
        }
        if !(iso.max_gradient > 0.0 && iso.max_gradient.is_finite()) {
            return Err(self.err(
                span,
                format!(
                    "the isosurface's max_gradient {} must be positive",
                    iso.max_gradient
                ),
            ));
        }
        Ok(())
    }

    /// `{ box { a, b } }` or `{ sphere { c, r } }` after `contained_by`.
    fn container(&mut self) -> R<Container> {
        let open = self.expect(Punct::LBrace, "after `contained_by`")?;
        self.enter(open.span)?;
        let r = self.container_shape();
        self.leave();
        let c = r?;
        self.expect(Punct::RBrace, "to close `contained_by`")?;
        Ok(c)
    }

    fn container_shape(&mut self) -> R<Container> {
        let tok = self.peek()?;
        let word = tok.ident().unwrap_or("");
        if word != "box" && word != "sphere" {
            return Err(self.expected("`box` or `sphere` in `contained_by`", &tok));
        }
        let open = self.block_start(word)?;
        let a = self.vector3()?;
        self.eat(Punct::Comma)?;
        let c = if word == "box" {
            let b = self.vector3()?;
            Container::Box {
                min: a.min(b),
                max: a.max(b),
            }
        } else {
            let (v, s) = self.expr()?;
            let radius = match v {
                Value::Float(r) => r,
                other => {
                    return Err(self.err(
                        s,
                        format!("expected the radius, found {}", other.kind_name()),
                    ));
                }
            };
            Container::Sphere { center: a, radius }
        };
        self.block_end(open, &format!("the {word}"))?;
        Ok(c)
    }
}
