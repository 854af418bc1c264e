//! `superellipsoid { <e, n> }` and `blob { threshold t sphere {...} cylinder {...} ... }`.

use std::sync::Arc;

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::ObjectValue;
use crate::scene::{Blob, BlobComponent, BlobComponentKind, Object, Shape, Transform};

type R<T> = Result<T, Diagnostic>;

fn shape(s: Shape) -> ObjectValue {
    ObjectValue {
        object: Some(Object::new(s)),
        ..ObjectValue::default()
    }
}

impl Evaluator<'_> {
    /// `superellipsoid { <e, n> }`: POV-Ray's east-west and north-south exponents; a
    /// float e reads as <e, e> (measured: the same image).
    pub(super) fn superellipsoid(&mut self) -> R<ObjectValue> {
        let (v, s) = self.expr()?;
        let v = self.to_vec3(&v, s)?;
        let (east_west, north_south) = (v.x, v.y);
        if !(east_west > 0.0 && north_south > 0.0) {
            return Err(self.err(
                s,
                format!(
                    "the superellipsoid's exponents <{east_west}, {north_south}> must be positive"
                ),
            ));
        }
        Ok(shape(Shape::Superellipsoid {
            east_west,
            north_south,
        }))
    }

    /// The blob's own items, up to its object modifiers: `threshold`, the components
    /// (`sphere`, `cylinder`, the old `component s, r, <c>`), `sturm`, `hierarchy`.
    pub(super) fn blob_items(&mut self, kw: &Token) -> R<ObjectValue> {
        let mut blob = Blob {
            threshold: 1.0,
            components: Vec::new(),
        };
        loop {
            let tok = self.peek()?;
            match tok.ident() {
                Some("threshold") => {
                    self.next()?;
                    blob.threshold = self.float()?;
                }
                Some(w @ ("sphere" | "cylinder")) => {
                    let c = self.blob_component(w == "cylinder")?;
                    self.count_objects(1, std::mem::size_of::<BlobComponent>(), tok.span)?;
                    blob.components.push(c);
                }
                Some("component") => {
                    self.next()?;
                    let strength = self.float()?;
                    self.eat(Punct::Comma)?;
                    let radius = self.float()?;
                    self.eat(Punct::Comma)?;
                    let center = self.vector3()?;
                    blob.components.push(BlobComponent {
                        kind: BlobComponentKind::Sphere { center },
                        radius,
                        strength,
                        transform: Transform::IDENTITY,
                        texture: None,
                    });
                }
                Some("sturm" | "hierarchy") => {
                    self.next()?;
                    self.optional_bool()?;
                }
                _ => break,
            }
        }
        if blob.components.is_empty() {
            return Err(self.err(kw.span, "this blob has no components"));
        }
        if blob.threshold.is_nan() || blob.threshold <= 0.0 {
            return Err(self.err(
                kw.span,
                format!("the blob's threshold {} must be positive", blob.threshold),
            ));
        }
        Ok(shape(Shape::Blob(blob)))
    }

    /// `sphere { <c>, r, [strength] s ... }` or `cylinder { <a>, <b>, r, [strength] s ... }`
    /// inside a blob, with the component's transforms.
    fn blob_component(&mut self, cylinder: bool) -> R<BlobComponent> {
        let word = if cylinder { "cylinder" } else { "sphere" };
        let open = self.block_start(word)?;
        let what = format!("the blob's {word}");
        let first = self.vector3()?;
        self.eat(Punct::Comma)?;
        let kind = if cylinder {
            let second = self.vector3()?;
            self.eat(Punct::Comma)?;
            if (second - first).length() < 1e-9 {
                return Err(self.err(
                    open.span,
                    "degenerate blob cylinder: its two ends are the same point",
                ));
            }
            BlobComponentKind::Cylinder {
                end1: first,
                end2: second,
            }
        } else {
            BlobComponentKind::Sphere { center: first }
        };
        let (v, s) = self.expr()?;
        let radius = self.to_float(&v, s)?;
        if radius.is_nan() || radius <= 0.0 {
            return Err(self.err(s, format!("the radius {radius} must be positive")));
        }
        self.eat(Punct::Comma)?;
        if self.peek()?.is_ident("strength") {
            self.next()?;
        }
        let strength = self.float()?;
        let mut transform = Transform::IDENTITY;
        // The component's texture is read as an object's is; a transform moves what is
        // read before it.
        let mut looks = Object::new(Shape::Union(Vec::new()));
        let mut textures = 0;
        loop {
            if let Some(t) = self.transform_modifier()? {
                transform = transform.then(&t);
                if let Some(texture) = &mut looks.texture {
                    Arc::make_mut(texture).transform_by(&t);
                }
                continue;
            }
            let tok = self.peek()?;
            match tok.ident() {
                _ if tok.is_punct(Punct::RBrace) => break,
                Some("texture") => self.texture_layer(&mut looks, &mut textures)?,
                Some(w @ ("pigment" | "finish" | "normal")) => {
                    self.appearance_modifier(&mut looks, w)?;
                }
                _ => return Err(self.stray_in_block(&tok, &what)),
            }
        }
        self.block_end(open, &what)?;
        Ok(BlobComponent {
            kind,
            radius,
            strength,
            transform,
            texture: looks.texture,
        })
    }
}
