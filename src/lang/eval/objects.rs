//! Shapes, CSG and the modifiers every object takes. Transforms compose in world space as
//! they are met (see `Object::transform_by`): a texture attached before a transform moves
//! with it, one attached after does not.

use std::sync::Arc;

use glam::{DAffine3, DMat3, DVec3};

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::{ObjectValue, Value};
use crate::scene::{Cone, Cylinder, Disc, Interior, Object, Shape, SmoothTriangle, Transform};

type R<T> = Result<T, Diagnostic>;

/// What reading a shape's own items (before its modifiers) gave.
enum ShapeRead {
    Kept(Box<ObjectValue>),
    /// POV-Ray drops the shape with a warning; its modifiers are still read.
    Dropped,
    /// `--skip-unsupported` left the whole object out, closing brace and all.
    Skipped,
}

/// Reads a shape's items after its `{`, given its keyword.
type ShapeReader = fn(&mut Evaluator<'_>, &Token) -> R<ShapeRead>;

fn kept(o: ObjectValue) -> R<ShapeRead> {
    Ok(ShapeRead::Kept(Box::new(o)))
}

/// Every keyword that starts an object, with its reader: the one list both "is this an
/// object?" and the reading itself use.
const SHAPES: &[(&str, ShapeReader)] = &[
    ("sphere", |ev, _| kept(ev.sphere()?)),
    ("plane", |ev, _| kept(ev.plane()?)),
    ("box", |ev, _| kept(ev.box_shape()?)),
    ("union", |ev, kw| {
        kept(ev.csg_children(the(kw), Shape::Union)?)
    }),
    ("object", |ev, _| ev.object_reference()),
    ("cylinder", |ev, kw| kept(ev.cylinder(kw)?)),
    ("cone", |ev, kw| kept(ev.cone(kw)?)),
    ("disc", |ev, _| ev.disc()),
    ("torus", |ev, _| kept(ev.torus()?)),
    ("quadric", |ev, _| kept(ev.quadric()?)),
    ("quartic", |ev, _| kept(ev.quartic()?)),
    ("triangle", |ev, kw| ev.triangle(kw, false)),
    ("smooth_triangle", |ev, kw| ev.triangle(kw, true)),
    ("mesh", |ev, kw| kept(ev.mesh_items(kw)?)),
    ("polygon", |ev, kw| kept(ev.polygon_items(kw)?)),
    ("prism", |ev, kw| kept(ev.prism_items(kw)?)),
    ("sor", |ev, _| kept(ev.sor_items()?)),
    ("lathe", |ev, _| kept(ev.lathe_items()?)),
    ("merge", |ev, kw| {
        kept(ev.csg_children(the(kw), Shape::Merge)?)
    }),
    ("intersection", |ev, kw| {
        kept(ev.csg_children(the(kw), Shape::Intersection)?)
    }),
    ("difference", |ev, kw| {
        kept(ev.csg_children(the(kw), Shape::Difference)?)
    }),
    ("superellipsoid", |ev, _| kept(ev.superellipsoid()?)),
    ("blob", |ev, kw| kept(ev.blob_items(kw)?)),
    ("isosurface", |ev, kw| kept(ev.isosurface_items(kw)?)),
    ("text", |ev, kw| kept(ev.text_items(kw)?)),
    ("mesh2", |ev, kw| kept(ev.mesh2_items(kw)?)),
    ("bicubic_patch", |ev, kw| kept(ev.bicubic_items(kw)?)),
    ("height_field", |ev, kw| {
        match ev.height_field_items(kw)? {
            Some(o) => kept(o),
            None => Ok(ShapeRead::Skipped),
        }
    }),
    ("poly", |ev, _| kept(ev.poly_items()?)),
    ("cubic", |ev, _| kept(ev.cubic_items()?)),
    ("polynomial", |ev, _| kept(ev.polynomial_items()?)),
    ("julia_fractal", |ev, _| kept(ev.julia_items()?)),
    ("light_group", |ev, kw| kept(ev.light_group_items(kw)?)),
];

/// "the sphere" for messages about the block `kw` opens: made once per keyword (a loop
/// making a million spheres asked for it a million times).
fn the(kw: &Token) -> &'static str {
    thread_local! {
        static THE: std::cell::RefCell<std::collections::HashMap<&'static str, &'static str>> =
            Default::default();
    }
    let word = kw.ident().unwrap_or("");
    THE.with_borrow_mut(|m| {
        *m.entry(word)
            .or_insert_with(|| crate::lang::parse::intern(&format!("the {word}")))
    })
}

pub fn is_object_keyword(word: &str) -> bool {
    SHAPES.iter().any(|(name, _)| *name == word)
}

/// Shapes and CSG kinds POV-Ray has that the scene model does not (yet).
pub fn is_known_unsupported_shape(word: &str) -> bool {
    matches!(word, "parametric" | "ovus" | "sphere_sweep")
}

impl Evaluator<'_> {
    /// An object starting at its keyword (`sphere`, `union`, `object`, ...).
    pub(super) fn object(&mut self) -> R<ObjectValue> {
        let kw = self.peek()?;
        let word = kw.ident().unwrap_or("");
        let open = self.block_start(word)?;
        let what = the(&kw);
        self.count_objects(1, super::budget::OBJECT_BYTES, kw.span)?;
        let read = match SHAPES.iter().find(|(name, _)| *name == word) {
            Some((_, reader)) => reader(self, &kw)?,
            None => self.object_reference()?,
        };
        let (mut o, dropped) = match read {
            ShapeRead::Kept(o) => (*o, false),
            ShapeRead::Dropped => (shape(Shape::Union(Vec::new())), true),
            ShapeRead::Skipped => {
                self.leave();
                return Ok(ObjectValue::default());
            }
        };
        self.modifiers(&mut o, what)?;
        self.block_end(open, what)?;
        let empty_csg = o.lights.is_empty()
            && o.object
                .as_ref()
                .is_some_and(|x| x.shape.children().is_some_and(|c| c.is_empty()));
        if dropped || empty_csg {
            return Ok(ObjectValue::default());
        }
        Ok(o)
    }

    fn sphere(&mut self) -> R<ObjectValue> {
        let center = self.vector3()?;
        self.eat(Punct::Comma)?;
        let (v, s) = self.expr()?;
        let radius = self.to_float(&v, s)?;
        Ok(shape(Shape::Sphere { center, radius }))
    }

    fn plane(&mut self) -> R<ObjectValue> {
        let (v, s) = self.expr()?;
        let normal = self.to_vec3(&v, s)?;
        let len = normal.length();
        if len == 0.0 || !len.is_finite() {
            return Err(self.err(s, "the plane's normal has zero length"));
        }
        self.eat(Punct::Comma)?;
        let distance = self.float()?;
        // POV-Ray normalises the normal and keeps the distance as written.
        Ok(shape(Shape::Plane {
            normal: normal / len,
            distance,
        }))
    }

    fn box_shape(&mut self) -> R<ObjectValue> {
        let corner1 = self.vector3()?;
        self.eat(Punct::Comma)?;
        let corner2 = self.vector3()?;
        Ok(shape(Shape::Box { corner1, corner2 }))
    }

    fn cylinder(&mut self, kw: &Token) -> R<ObjectValue> {
        let base = self.vector3()?;
        self.eat(Punct::Comma)?;
        let cap = self.vector3()?;
        self.eat(Punct::Comma)?;
        let radius = self.float()?;
        if (cap - base).length() < 1e-9 {
            return Err(self.err(
                kw.span,
                "degenerate cylinder: the base point equals the cap point",
            ));
        }
        Ok(shape(Shape::Cylinder(Box::new(Cylinder {
            base,
            cap,
            radius,
            open: false,
        }))))
    }

    fn cone(&mut self, kw: &Token) -> R<ObjectValue> {
        let base = self.vector3()?;
        self.eat(Punct::Comma)?;
        let base_radius = self.float()?;
        self.eat(Punct::Comma)?;
        let cap = self.vector3()?;
        self.eat(Punct::Comma)?;
        let cap_radius = self.float()?;
        if (cap - base).length() < 1e-9 {
            return Err(self.err(
                kw.span,
                "degenerate cone: the base point equals the cap point",
            ));
        }
        Ok(shape(Shape::Cone(Box::new(Cone {
            base,
            base_radius,
            cap,
            cap_radius,
            open: false,
        }))))
    }

    fn disc(&mut self) -> R<ShapeRead> {
        let center = self.vector3()?;
        self.eat(Punct::Comma)?;
        let (v, s) = self.expr()?;
        let normal = self.to_vec3(&v, s)?;
        self.eat(Punct::Comma)?;
        let radius = self.float()?;
        let hole_radius = if self.eat(Punct::Comma)? {
            self.float()?
        } else {
            0.0
        };
        let len = normal.length();
        if len < 1e-12 || !len.is_finite() {
            // POV-Ray accepts it and shows nothing; say so and leave it out.
            self.warn(s, "the disc's normal has zero length; the disc is left out");
            return Ok(ShapeRead::Dropped);
        }
        kept(shape(Shape::Disc(Box::new(Disc {
            center,
            normal: normal / len,
            radius,
            hole_radius,
        }))))
    }

    fn torus(&mut self) -> R<ObjectValue> {
        let major = self.float()?;
        self.eat(Punct::Comma)?;
        let minor = self.float()?;
        Ok(shape(Shape::Torus { major, minor }))
    }

    fn quadric(&mut self) -> R<ObjectValue> {
        let abc = self.vector3()?;
        self.eat(Punct::Comma)?;
        let def = self.vector3()?;
        self.eat(Punct::Comma)?;
        let ghi = self.vector3()?;
        self.eat(Punct::Comma)?;
        let j = self.float()?;
        Ok(shape(Shape::Quadric(Box::new([
            abc.x, abc.y, abc.z, def.x, def.y, def.z, ghi.x, ghi.y, ghi.z, j,
        ]))))
    }

    /// `quartic { <a0, ..., a34> }`: 35 coefficients, too many for a vector value.
    fn quartic(&mut self) -> R<ObjectValue> {
        self.expect(Punct::Lt, "to open the quartic's 35 coefficients")?;
        let mut coefficients = Vec::with_capacity(35);
        for i in 0..35 {
            if i > 0 {
                self.eat(Punct::Comma)?;
            }
            let (v, sp) = self.additive()?;
            coefficients.push(self.to_float(&v, sp)?);
        }
        self.expect(Punct::Gt, "after the quartic's 35 coefficients")?;
        Ok(shape(Shape::Quartic { coefficients }))
    }

    fn triangle(&mut self, kw: &Token, smooth: bool) -> R<ShapeRead> {
        let (tri, degenerate) = self.triangle_items(smooth)?;
        if degenerate {
            // As POV-Ray: a warning, and the triangle is dropped.
            self.warn(kw.span, "degenerate triangle; it is left out");
            return Ok(ShapeRead::Dropped);
        }
        kept(shape(match tri.normals {
            Some(normals) => Shape::SmoothTriangle(Box::new(SmoothTriangle {
                corners: tri.corners,
                normals,
            })),
            None => Shape::Triangle(Box::new(tri.corners)),
        }))
    }

    /// A bare object identifier, read as `object { Name }` would be: POV-Ray places one at
    /// the top level and takes one in `looks_like` (measured: the same image). `None` when
    /// the next token is not one.
    pub(super) fn named_object(&mut self) -> R<Option<ObjectValue>> {
        let tok = self.peek()?;
        let Some(Value::Object(o)) = tok.ident().and_then(|n| self.lookup(n)).cloned() else {
            return Ok(None);
        };
        self.next()?;
        self.count_objects(1, super::budget::OBJECT_BYTES, tok.span)?;
        Ok(Some(*o))
    }

    /// `object { Name ... }`, `object { Shapes[i] ... }` or `object { sphere {...} ... }`.
    fn object_reference(&mut self) -> R<ShapeRead> {
        if self.skip_unsupported
            && let Some(raw) = self.raw_peek(0).cloned()
            && let Some(Value::Unsupported(d)) = raw.ident().and_then(|n| self.lookup(n))
        {
            // Leave the whole object out: the rest of its block, its brace.
            let message = format!("{}; the object is left out", d.message);
            self.warn(raw.span, message);
            self.skip_rest_of_block()?;
            return Ok(ShapeRead::Skipped);
        }
        let tok = self.peek()?;
        match tok.ident().and_then(|n| self.lookup(n)).cloned() {
            Some(Value::Object(o)) => {
                self.next()?;
                Ok(ShapeRead::Kept(o))
            }
            // `object { Shapes[i] }`
            Some(Value::Array(_)) => match self.expr()? {
                (Value::Object(o), _) => Ok(ShapeRead::Kept(o)),
                (Value::Unsupported(d), s) => Err(self.err(s, d.message.clone())),
                (other, s) => Err(self.err(
                    s,
                    format!("expected an object, found {}", other.kind_name()),
                )),
            },
            Some(other) => Err(self.err(
                tok.span,
                format!("expected an object identifier, found {}", other.kind_name()),
            )),
            None => {
                if is_object_keyword(tok.ident().unwrap_or("")) {
                    kept(self.object()?)
                } else if let Some(w) = tok.ident() {
                    if is_known_unsupported_shape(w) {
                        return Err(self.unsupported(&tok, w));
                    }
                    Err(self.unknown_identifier(&tok, w))
                } else {
                    Err(self.expected("an object identifier", &tok))
                }
            }
        }
    }

    /// `light_group { objects... lights... }`: a union whose objects only its own lights
    /// shade (and the global lights, with `global_lights on`, read as a modifier). Nested
    /// groups keep their own: the innermost group an object is in decides.
    fn light_group_items(&mut self, kw: &Token) -> R<ObjectValue> {
        let mut group = self.csg_children(the(kw), Shape::Union)?;
        let id = self.light_groups;
        self.light_groups += 1;
        for light in &mut group.lights {
            light.group.get_or_insert(id);
        }
        if let Some(o) = &mut group.object {
            o.flags.light_group = Some(crate::scene::LightGroup {
                id,
                global_lights: false,
            });
        }
        Ok(group)
    }

    /// Children of a CSG block; lights inside it are kept beside the shape so later
    /// transforms move them too. Children without a texture keep `None` (they inherit).
    fn csg_children(&mut self, what: &str, make: fn(Vec<Object>) -> Shape) -> R<ObjectValue> {
        let first = self.peek()?.span;
        let mut skipped = false;
        let mut children = Vec::new();
        let mut lights = Vec::new();
        loop {
            let tok = self.peek()?;
            let Some(word) = tok.ident() else { break };
            if is_object_keyword(word) {
                let child = self.object()?;
                skipped |= child.object.is_none() && child.lights.is_empty();
                children.extend(child.object);
                lights.extend(child.lights);
            } else if word == "light_source" {
                lights.push(self.light_source()?);
            } else if is_known_unsupported_shape(word) && self.lookup(word).is_none() {
                let word = word.to_string();
                self.unsupported_or_skip(&tok, &word)?;
                skipped = true;
            } else {
                break;
            }
        }
        // POV-Ray accepts an empty CSG block (a loop that made nothing, say) silently; it
        // is left out of the scene after its modifiers are read.
        let _ = skipped;
        let shape = make(children);
        if !matches!(shape, Shape::Union(_)) && shape.children().is_some_and(|c| c.len() < 2) {
            self.warn(first, format!("{what} should have at least 2 objects"));
        }
        Ok(ObjectValue {
            object: Some(Object::new(shape)),
            lights,
        })
    }

    /// Transforms, textures and flags, until the closing brace.
    fn modifiers(&mut self, o: &mut ObjectValue, what: &str) -> R<()> {
        let mut textures = 0;
        let mut bounds: Vec<Object> = Vec::new();
        let mut clipped: Vec<Object> = Vec::new();
        let mut uv_mapping = false;
        loop {
            let tok = self.peek()?;
            if tok.is_punct(punct_close()) {
                return Ok(());
            }
            let Some(word) = tok.ident() else {
                return Err(self.stray_in_block(&tok, what));
            };
            if let Some(t) = self.transform_modifier()? {
                o.transform_by(&t);
                continue;
            }
            let Some(object) = o.object.as_mut() else {
                return Err(self.stray_in_block(&tok, what));
            };
            // Modifiers other than transforms make a shared object this one's own.
            object.unshared();
            let known = match word {
                "texture" => {
                    self.texture_layer(object, &mut textures)?;
                    true
                }
                // The textures that follow read the surface's (u, v), as `texture {
                // uv_mapping ... }` does (measured: the same pixels); POV-Ray refuses it
                // after a texture.
                "uv_mapping" => {
                    if object.texture.is_some() {
                        return Err(self.err(
                            tok.span,
                            "`uv_mapping` must come before the object's texture",
                        ));
                    }
                    self.next()?;
                    uv_mapping = true;
                    true
                }
                "clipped_by" => {
                    self.next()?;
                    let clips = self.object_list("clipped_by", "bounded_by", &bounds)?;
                    object
                        .clipping_mut()
                        .clipped_by
                        .extend(clips.iter().cloned());
                    clipped = clips;
                    true
                }
                // Bounds only speed POV-Ray up, and penumbra builds its own, except on a
                // quartic, where POV-Ray keeps them and a ray that misses the bound misses
                // the surface (measured: a poly sphere bounded by a smaller sphere shows the
                // small sphere's outline). Infinite quartics are cut off this way.
                "bounded_by" => {
                    self.next()?;
                    bounds = self.object_list("bounded_by", "clipped_by", &clipped)?;
                    if matches!(object.shape, Shape::Quartic { .. } | Shape::Poly { .. }) {
                        object.clipping_mut().bounded_by.clone_from(&bounds);
                    }
                    true
                }
                w => self.appearance_modifier(object, w)? || self.flag_modifier(object, &tok, w)?,
            };
            // Marked as read, before later transforms of the object reach it.
            if uv_mapping && let Some(t) = object.texture.as_mut() {
                super::texture::mark_uv_mapped(Arc::make_mut(t));
            }
            if !known {
                return Err(self.stray_in_block(&tok, what));
            }
        }
    }

    /// `texture { }`: the object's `textures`-th. A second layers over the first; the first
    /// replaces the default.
    pub(super) fn texture_layer(&mut self, object: &mut Object, textures: &mut u32) -> R<()> {
        *textures += 1;
        self.next()?;
        let top = self.texture_body(self.default_texture.clone())?;
        let below = if *textures > 1 {
            object.texture.take().map(Arc::unwrap_or_clone)
        } else {
            None
        };
        object.texture = Some(self.share_texture(Self::layer_texture(below, top)));
        Ok(())
    }

    /// `pigment`, `finish`, `normal`, `interior`, `material`; false for other words.
    pub(super) fn appearance_modifier(&mut self, object: &mut Object, word: &str) -> R<bool> {
        match word {
            "pigment" if object.texture.is_none() => {
                self.next()?;
                let pigment = self.pigment_body(self.default_texture.pigment.clone())?;
                object.texture = Some(self.default_texture_with(pigment));
            }
            "pigment" => self.edit_texture(object, |ev, t| {
                t.pigment = ev.pigment_body(std::mem::take(&mut t.pigment))?;
                Ok(())
            })?,
            "finish" => self.edit_texture(object, |ev, t| {
                t.finish = ev.finish_body(t.finish)?;
                Ok(())
            })?,
            "normal" => self.edit_texture(object, |ev, t| {
                t.normal = ev.normal_body(t.normal.take())?;
                Ok(())
            })?,
            "interior" => {
                self.next()?;
                self.object_interior(object)?;
            }
            "material" => {
                self.next()?;
                self.material_body(object)?;
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// The default texture with `pigment`, shared with the last object that had the same.
    fn default_texture_with(
        &mut self,
        pigment: crate::scene::Pigment,
    ) -> Arc<crate::scene::Texture> {
        if let Some(t) = &self.default_with_pigment
            && t.pigment == pigment
        {
            return t.clone();
        }
        let texture = crate::scene::Texture {
            pigment,
            ..self.default_texture.clone()
        };
        let shared = self.share_texture(texture);
        self.default_with_pigment = Some(shared.clone());
        shared
    }

    /// A texture item outside a `texture` block changes the object's texture, or the
    /// default texture when the object has none yet. Edited in place: a texture is large,
    /// and a loop of a million objects moves it once per object rather than four times.
    fn edit_texture(
        &mut self,
        object: &mut Object,
        edit: impl FnOnce(&mut Self, &mut crate::scene::Texture) -> R<()>,
    ) -> R<()> {
        self.next()?;
        let mut texture = object
            .texture
            .take()
            .map_or_else(|| self.default_texture.clone(), Arc::unwrap_or_clone);
        edit(self, &mut texture)?;
        object.texture = Some(self.share_texture(texture));
        Ok(())
    }

    /// Object flags, and keywords read but without effect; false for other words.
    fn flag_modifier(&mut self, object: &mut Object, tok: &Token, word: &str) -> R<bool> {
        match word {
            "no_shadow" => flag(self, &mut object.flags.no_shadow)?,
            "no_image" => flag(self, &mut object.flags.no_image)?,
            "no_reflection" => flag(self, &mut object.flags.no_reflection)?,
            "double_illuminate" => flag(self, &mut object.flags.double_illuminate)?,
            "global_lights" => {
                let Some(group) = &mut object.flags.light_group else {
                    return Err(self.err(tok.span, "`global_lights` only applies to a light_group"));
                };
                self.next()?;
                group.global_lights = self.optional_bool()?;
            }
            "hollow" => {
                self.next()?;
                object.flags.hollow = self.optional_bool()?;
            }
            "inverse" => {
                self.next()?;
                object.flags.inverse = !object.flags.inverse;
            }
            "open" => {
                self.next()?;
                match &mut object.shape {
                    Shape::Cylinder(c) => c.open = true,
                    Shape::Cone(c) => c.open = true,
                    Shape::Prism(prism) => prism.open = true,
                    Shape::Sor(sor) => sor.open = true,
                    _ => self.warn(
                        tok.span,
                        "`open` only applies to cylinders, cones, prisms and sors",
                    ),
                }
            }
            // Root solving is exact enough in penumbra without `sturm`.
            "sturm" | "split_union" | "cutaway_textures" => {
                self.next()?;
                self.optional_bool()?;
            }
            "interior_texture" => {
                self.next()?;
                let t = self.texture_body(self.default_texture.clone())?;
                object.interior_texture = Some(self.share_texture(t));
            }
            "no_radiosity" => flag(self, &mut object.flags.no_radiosity)?,
            "radiosity" => self.object_radiosity()?,
            "photons" => {
                let start = object.flags.photons.unwrap_or_default();
                object.flags.photons = Some(self.object_photons(start)?);
            }
            _ => return Ok(false),
        }
        Ok(true)
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
        self.block_items(
            "transform",
            "the transform",
            Transform::IDENTITY,
            |ev, tok, t| {
                if tok.is_ident("inverse") {
                    ev.next()?;
                    *t = t.inverted();
                    return Ok(());
                }
                if let Some(Value::Transform(named)) =
                    tok.ident().and_then(|n| ev.lookup(n)).cloned()
                {
                    ev.next()?;
                    *t = t.then(&named);
                    return Ok(());
                }
                match ev.transform_modifier()? {
                    Some(step) => *t = t.then(&step),
                    None => return Err(ev.stray_in_block(tok, "the transform")),
                }
                Ok(())
            },
        )
    }

    /// `interior { ... }` on an object: edits the interior it has, else the default one.
    fn object_interior(&mut self, object: &mut Object) -> R<()> {
        let base = object
            .interior
            .take()
            .map_or_else(Interior::default, |i| *i);
        object.interior = Some(Box::new(self.interior_body(base)?));
        Ok(())
    }

    pub(super) fn interior_body(&mut self, interior: Interior) -> R<Interior> {
        self.block_items("interior", "the interior", interior, |ev, tok, interior| {
            match tok.ident() {
                Some("ior") => {
                    ev.next()?;
                    interior.ior = ev.float()?;
                }
                Some(n) if matches!(ev.lookup(n), Some(Value::Interior(_))) => {
                    if let Some(Value::Interior(i)) = ev.lookup(n).cloned() {
                        *interior = *i;
                    }
                    ev.next()?;
                }
                Some(w @ ("fade_distance" | "fade_power" | "fade_color" | "fade_colour")) => {
                    let w = w.to_string();
                    ev.next()?;
                    ev.interior_fade_item(&w, interior)?;
                }
                Some(w @ ("caustics" | "dispersion" | "dispersion_samples")) => {
                    let w = w.to_string();
                    ev.next()?;
                    ev.interior_light_item(&w, interior)?;
                }
                Some("media") => {
                    let media = ev.media()?;
                    interior.media.push(media);
                }
                _ => return Err(ev.stray_in_block(tok, "the interior")),
            }
            Ok(())
        })
    }
}

/// Corners (and normals) of one triangle as written.
pub(super) struct TriangleItems {
    pub(super) corners: [DVec3; 3],
    pub(super) normals: Option<[DVec3; 3]>,
}

/// Collinear or coincident corners: POV-Ray drops such triangles.
pub(super) fn degenerate_triangle(c: &[DVec3; 3]) -> bool {
    let e1 = c[1] - c[0];
    let e2 = c[2] - c[0];
    let n = e1.cross(e2).length();
    !(n.is_finite() && n > 1e-12 * e1.length() * e2.length() && n > 0.0)
}

impl Evaluator<'_> {
    /// The corners of a `triangle` (or corners and normals of a `smooth_triangle`), after
    /// the opening brace; whether they are degenerate.
    pub(super) fn triangle_items(&mut self, smooth: bool) -> R<(TriangleItems, bool)> {
        let mut corners = [DVec3::ZERO; 3];
        let mut normals = [DVec3::ZERO; 3];
        for i in 0..3 {
            if i > 0 {
                self.eat(Punct::Comma)?;
            }
            corners[i] = self.vector3()?;
            if smooth {
                self.eat(Punct::Comma)?;
                normals[i] = self.vector3()?;
            }
        }
        let degenerate = degenerate_triangle(&corners);
        Ok((
            TriangleItems {
                corners,
                normals: smooth.then_some(normals),
            },
            degenerate,
        ))
    }

    /// `polygon { n, p1, ..., pn }`: 2-D points lie in z = 0. A last sub-polygon that does
    /// not return to its first point is closed, with a warning, as in POV-Ray.
    fn polygon_items(&mut self, kw: &Token) -> R<ObjectValue> {
        let (v, s) = self.expr()?;
        let n = self.to_float(&v, s)?;
        if !(3.0..=1e7).contains(&n) {
            return Err(self.err(
                s,
                format!("a polygon needs at least three points, found {n}"),
            ));
        }
        let n = n as usize;
        self.count_objects(1, n * std::mem::size_of::<DVec3>(), s)?;
        let mut points = Vec::with_capacity(n.min(1 << 16));
        let mut first = 0;
        for i in 0..n {
            self.eat(Punct::Comma)?;
            let p = self.vector3()?;
            points.push(p);
            if i > first && p == points[first] {
                first = i + 1;
            }
        }
        if first < points.len() {
            self.warn(kw.span, "the polygon is not closed; closing it");
            let p = points[first];
            points.push(p);
        }
        Ok(shape(Shape::Polygon { points }))
    }

    /// `{ objects }` after `clipped_by` or `bounded_by`; `{ other }` (the other keyword
    /// alone) means the objects given to the other one.
    fn object_list(&mut self, what: &str, other: &str, others: &[Object]) -> R<Vec<Object>> {
        let close = format!("`{what}`");
        self.block_items(what, &close, Vec::new(), |ev, tok, out| {
            if tok.is_ident(other) {
                ev.next()?;
                out.extend(others.iter().cloned());
                return Ok(());
            }
            match tok.ident() {
                Some(w) if is_object_keyword(w) => {
                    let o = ev.object()?;
                    out.extend(o.object);
                }
                Some(w) if is_known_unsupported_shape(w) && ev.lookup(w).is_none() => {
                    let w = w.to_string();
                    ev.unsupported_or_skip(tok, &w)?;
                }
                _ => return Err(ev.stray_in_block(tok, &close)),
            }
            Ok(())
        })
    }

    /// `material { [Name] texture {...} interior {...} transforms }`.
    pub(super) fn material_body(&mut self, object: &mut Object) -> R<()> {
        self.block_items("material", "the material", (), |ev, tok, ()| {
            match tok.ident() {
                Some("texture") => {
                    ev.next()?;
                    let t = ev.texture_body(ev.default_texture.clone())?;
                    object.texture = Some(ev.share_texture(t));
                }
                Some("interior") => {
                    ev.next()?;
                    ev.object_interior(object)?;
                }
                Some(n) if matches!(ev.lookup(n), Some(Value::Material(_) | Value::Array(_))) => {
                    // A material identifier, or an element of an array of them.
                    let (v, s) = ev.expr()?;
                    let Value::Material(m) = v else {
                        return Err(
                            ev.err(s, format!("expected a material, found {}", v.kind_name()))
                        );
                    };
                    if let Some(t) = m.0 {
                        object.texture = Some(ev.share_texture(t));
                    }
                    if m.1.is_some() {
                        object.interior = m.1.map(Box::new);
                    }
                }
                _ => match ev.transform_modifier()? {
                    Some(t) => {
                        if let Some(texture) = &mut object.texture {
                            Arc::make_mut(texture).transform_by(&t);
                        }
                    }
                    None => return Err(ev.stray_in_block(tok, "the material")),
                },
            }
            Ok(())
        })
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
