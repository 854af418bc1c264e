//! Shapes, CSG and the modifiers every object takes. Transforms compose in world space as
//! they are met (see `Object::transform_by`): a texture attached before a transform moves
//! with it, one attached after does not.

use glam::{DAffine3, DMat3, DVec3};

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::{ObjectValue, Value};
use crate::scene::{Interior, Object, Shape, Transform};

type R<T> = Result<T, Diagnostic>;

pub fn is_object_keyword(word: &str) -> bool {
    matches!(word, "sphere" | "plane" | "box" | "union" | "object")
}

/// Shapes and CSG kinds POV-Ray has that the scene model does not (yet).
pub fn is_known_unsupported_shape(word: &str) -> bool {
    matches!(
        word,
        "cylinder"
            | "cone"
            | "torus"
            | "intersection"
            | "difference"
            | "merge"
            | "blob"
            | "mesh"
            | "mesh2"
            | "lathe"
            | "sor"
            | "prism"
            | "text"
            | "height_field"
            | "isosurface"
            | "parametric"
            | "superellipsoid"
            | "julia_fractal"
            | "bicubic_patch"
            | "disc"
            | "polygon"
            | "triangle"
            | "smooth_triangle"
            | "quadric"
            | "cubic"
            | "quartic"
            | "poly"
            | "polynomial"
            | "ovus"
            | "sphere_sweep"
            | "light_group"
    )
}

impl Evaluator<'_> {
    /// An object starting at its keyword (`sphere`, `union`, `object`, ...).
    pub(super) fn object(&mut self) -> R<ObjectValue> {
        let kw = self.peek()?;
        let word = kw.ident().unwrap_or("").to_string();
        let open = self.block_start(&word)?;
        let what = format!("the {word}");
        let mut o = match word.as_str() {
            "sphere" => {
                let center = self.vector3()?;
                self.eat(Punct::Comma)?;
                let (v, s) = self.expr()?;
                let radius = self.to_float(&v, s)?;
                shape(Shape::Sphere { center, radius })
            }
            "plane" => {
                let (v, s) = self.expr()?;
                let normal = self.to_vec3(&v, s)?;
                let len = normal.length();
                if len == 0.0 || !len.is_finite() {
                    return Err(self.err(s, "the plane's normal has zero length"));
                }
                self.eat(Punct::Comma)?;
                let distance = self.float()?;
                // POV-Ray normalises the normal and keeps the distance as written.
                shape(Shape::Plane {
                    normal: normal / len,
                    distance,
                })
            }
            "box" => {
                let corner1 = self.vector3()?;
                self.eat(Punct::Comma)?;
                let corner2 = self.vector3()?;
                shape(Shape::Box { corner1, corner2 })
            }
            "union" => self.union_children(&what)?,
            _ => {
                // `object { Name ... }`
                let tok = self.peek()?;
                match tok.ident().and_then(|n| self.lookup(n)).cloned() {
                    Some(Value::Object(o)) => {
                        self.next()?;
                        *o
                    }
                    Some(other) => {
                        return Err(self.err(
                            tok.span,
                            format!("expected an object identifier, found {}", other.kind_name()),
                        ));
                    }
                    None => {
                        if is_object_keyword(tok.ident().unwrap_or("")) {
                            self.object()?
                        } else if let Some(w) = tok.ident() {
                            if is_known_unsupported_shape(w) {
                                return Err(self.unsupported(&tok, w));
                            }
                            return Err(self.unknown_identifier(&tok, w));
                        } else {
                            return Err(self.expected("an object identifier", &tok));
                        }
                    }
                }
            }
        };
        self.modifiers(&mut o, &what)?;
        self.block_end(open, &what)?;
        Ok(o)
    }

    /// Children of a `union`; lights inside it are kept beside the shape so later
    /// transforms move them too. Children without a texture keep `None` (they inherit).
    fn union_children(&mut self, what: &str) -> R<ObjectValue> {
        let mut children = Vec::new();
        let mut lights = Vec::new();
        loop {
            let tok = self.peek()?;
            let Some(word) = tok.ident() else { break };
            if is_object_keyword(word) {
                let child = self.object()?;
                children.extend(child.object);
                lights.extend(child.lights);
            } else if word == "light_source" {
                lights.push(self.light_source()?);
            } else if is_known_unsupported_shape(word) && self.lookup(word).is_none() {
                return Err(self.unsupported(&tok, word));
            } else {
                break;
            }
        }
        if children.is_empty() && lights.is_empty() {
            let tok = self.peek()?;
            return Err(self.expected(&format!("objects inside {what}"), &tok));
        }
        Ok(ObjectValue {
            object: Some(Object::new(Shape::Union(children))),
            lights,
        })
    }

    /// Transforms, textures and flags, until the closing brace.
    fn modifiers(&mut self, o: &mut ObjectValue, what: &str) -> R<()> {
        let mut textures = 0;
        loop {
            let tok = self.peek()?;
            if tok.is_punct(punct_close()) {
                return Ok(());
            }
            let Some(word) = tok.ident().map(str::to_string) else {
                return Err(self.stray_in_block(&tok, what));
            };
            if let Some(t) = self.transform_modifier()? {
                o.transform_by(&t);
                continue;
            }
            let Some(object) = o.object.as_mut() else {
                return Err(self.stray_in_block(&tok, what));
            };
            match word.as_str() {
                "pigment" => {
                    self.next()?;
                    let mut texture = object
                        .texture
                        .take()
                        .unwrap_or_else(|| self.default_texture.clone());
                    texture.pigment = self.pigment_body(texture.pigment)?;
                    object.texture = Some(texture);
                }
                "finish" => {
                    self.next()?;
                    let mut texture = object
                        .texture
                        .take()
                        .unwrap_or_else(|| self.default_texture.clone());
                    texture.finish = self.finish_body(texture.finish)?;
                    object.texture = Some(texture);
                }
                "texture" => {
                    textures += 1;
                    self.next()?;
                    let top = self.texture_body(self.default_texture.clone())?;
                    let below = if textures > 1 {
                        object.texture.take()
                    } else {
                        None
                    };
                    object.texture = Some(Self::layer_texture(below, top));
                }
                "normal" => {
                    self.next()?;
                    let mut texture = object
                        .texture
                        .take()
                        .unwrap_or_else(|| self.default_texture.clone());
                    texture.normal = self.normal_body(texture.normal.take())?;
                    object.texture = Some(texture);
                }
                "interior" => {
                    self.next()?;
                    let base = object.interior.unwrap_or_default();
                    object.interior = Some(self.interior_body(base)?);
                }
                "no_shadow" => flag(self, &mut object.flags.no_shadow)?,
                "no_image" => flag(self, &mut object.flags.no_image)?,
                "no_reflection" => flag(self, &mut object.flags.no_reflection)?,
                "double_illuminate" => flag(self, &mut object.flags.double_illuminate)?,
                "hollow" => {
                    self.next()?;
                    object.flags.hollow = self.optional_bool()?;
                }
                "inverse" => {
                    self.next()?;
                    object.flags.inverse = !object.flags.inverse;
                }
                "bounded_by" | "clipped_by" | "photons" | "radiosity" | "material"
                | "interior_texture" | "sturm" | "open" | "split_union" | "cutaway_textures"
                | "no_radiosity" => return Err(self.unsupported(&tok, &word)),
                _ => return Err(self.stray_in_block(&tok, what)),
            }
        }
    }

    /// `translate`, `rotate`, `scale`, `matrix`, `transform`: the transform, if the next
    /// token is one of them.
    pub(super) fn transform_modifier(&mut self) -> R<Option<Transform>> {
        let tok = self.peek()?;
        let Some(word) = tok.ident() else {
            return Ok(None);
        };
        let t = match word {
            "translate" => {
                self.next()?;
                Transform::translate(self.vector3()?)
            }
            "rotate" => {
                self.next()?;
                Transform::rotate(self.vector3()?)
            }
            "scale" => {
                self.next()?;
                let (v, s) = self.expr()?;
                let v = self.to_vec3(&v, s)?;
                Transform::scale(v).ok_or_else(|| {
                    self.err(
                        s,
                        format!(
                            "a scale of <{}, {}, {}> has a zero component",
                            v.x, v.y, v.z
                        ),
                    )
                })?
            }
            "matrix" => {
                self.next()?;
                self.matrix(&tok)?
            }
            "transform" => {
                self.next()?;
                let next = self.peek()?;
                if next.is_punct(Punct::LBrace) {
                    self.transform_block_open()?
                } else {
                    match next.ident().and_then(|n| self.lookup(n)).cloned() {
                        Some(Value::Transform(t)) => {
                            self.next()?;
                            *t
                        }
                        _ => return Err(self.expected("`{` or a transform identifier", &next)),
                    }
                }
            }
            _ => return Ok(None),
        };
        Ok(Some(t))
    }

    /// `matrix <12 floats>`: rows are the images of x, y, z, then the translation.
    fn matrix(&mut self, tok: &Token) -> R<Transform> {
        let open = self.expect(Punct::Lt, "after `matrix`")?;
        let mut m = [0.0; 12];
        for (i, slot) in m.iter_mut().enumerate() {
            if i > 0 {
                self.expect(Punct::Comma, "between matrix values")?;
            }
            let saved = std::mem::replace(&mut self.in_vector, true);
            let r = self.float();
            self.in_vector = saved;
            *slot = r?;
        }
        let close = self.expect(Punct::Gt, "to close the matrix")?;
        let forward = DAffine3 {
            matrix3: DMat3::from_cols(
                DVec3::new(m[0], m[1], m[2]),
                DVec3::new(m[3], m[4], m[5]),
                DVec3::new(m[6], m[7], m[8]),
            ),
            translation: DVec3::new(m[9], m[10], m[11]),
        };
        Transform::from_affine(forward).ok_or_else(|| {
            self.err(
                tok.span.join(open.span).join(close.span),
                "this matrix is singular",
            )
        })
    }

    /// `transform { ... }` after the keyword.
    pub(super) fn transform_block(&mut self) -> R<Transform> {
        self.transform_block_open()
    }

    fn transform_block_open(&mut self) -> R<Transform> {
        let open = self.expect(Punct::LBrace, "after `transform`")?;
        self.enter(open.span)?;
        let r = (|| -> R<Transform> {
            let mut t = Transform::IDENTITY;
            loop {
                let tok = self.peek()?;
                if tok.is_punct(Punct::RBrace) {
                    return Ok(t);
                }
                if tok.is_ident("inverse") {
                    self.next()?;
                    t = t.inverted();
                    continue;
                }
                if let Some(Value::Transform(named)) =
                    tok.ident().and_then(|n| self.lookup(n)).cloned()
                {
                    self.next()?;
                    t = t.then(&named);
                    continue;
                }
                match self.transform_modifier()? {
                    Some(step) => t = t.then(&step),
                    None => return Err(self.stray_in_block(&tok, "the transform")),
                }
            }
        })();
        self.leave();
        let t = r?;
        self.expect(Punct::RBrace, "to close the transform")?;
        Ok(t)
    }

    pub(super) fn interior_body(&mut self, mut interior: Interior) -> R<Interior> {
        let open = self.expect(Punct::LBrace, "after `interior`")?;
        self.enter(open.span)?;
        let r = (|| -> R<Interior> {
            loop {
                let tok = self.peek()?;
                if tok.is_punct(Punct::RBrace) {
                    return Ok(interior);
                }
                match tok.ident() {
                    Some("ior") => {
                        self.next()?;
                        interior.ior = self.float()?;
                    }
                    Some(n) if matches!(self.lookup(n), Some(Value::Interior(_))) => {
                        if let Some(Value::Interior(i)) = self.lookup(n).cloned() {
                            interior = i;
                        }
                        self.next()?;
                    }
                    Some(w @ ("fade_distance" | "fade_power" | "fade_color" | "fade_colour")) => {
                        let w = w.to_string();
                        self.next()?;
                        self.interior_fade_item(&w, &mut interior)?;
                    }
                    Some(w @ ("caustics" | "dispersion" | "dispersion_samples" | "media")) => {
                        let w = w.to_string();
                        return Err(self.unsupported(&tok, &w));
                    }
                    _ => return Err(self.stray_in_block(&tok, "the interior")),
                }
            }
        })();
        self.leave();
        let i = r?;
        self.expect(Punct::RBrace, "to close the interior")?;
        Ok(i)
    }
}

fn punct_close() -> Punct {
    Punct::RBrace
}

fn shape(s: Shape) -> ObjectValue {
    ObjectValue {
        object: Some(Object::new(s)),
        lights: Vec::new(),
    }
}

fn flag(ev: &mut Evaluator<'_>, f: &mut bool) -> R<()> {
    ev.next()?;
    *f = true;
    Ok(())
}
