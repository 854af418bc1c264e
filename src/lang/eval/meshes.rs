//! `mesh`, `mesh2`, `height_field` and `bicubic_patch`: the shapes made of triangles.

use std::sync::Arc;

use glam::{DVec2, DVec3};

use super::super::diagnostics::{Diagnostic, Span};
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::{ObjectValue, Value};
use crate::scene::{BicubicPatch, Mesh, MeshFace, Object, Shape, Texture};

type R<T> = Result<T, Diagnostic>;

fn shape(s: Shape) -> ObjectValue {
    ObjectValue {
        object: Some(Object::new(s)),
        ..ObjectValue::default()
    }
}

use super::objects::degenerate_triangle as degenerate;

/// The faces as `face_indices` gives them, with where each was written.
struct FaceList {
    faces: Vec<MeshFace>,
}

impl Evaluator<'_> {
    /// `mesh { triangle {...} smooth_triangle {...} ... [inside_vector v] [hierarchy b] }`
    /// up to the object modifiers. Each triangle adds its own corners; a triangle's
    /// `texture` and `uv_vectors` are its own. Degenerate triangles are dropped silently,
    /// as POV-Ray does.
    pub(super) fn mesh_items(&mut self, kw: &Token) -> R<ObjectValue> {
        // `mesh { Name ... }`: a declared mesh, as the mesh_camera scenes write it.
        let first = self.peek()?;
        if let Some(super::value::Value::Object(o)) =
            first.ident().and_then(|w| self.lookup(w)).cloned()
            && o.object
                .as_ref()
                .is_some_and(|x| matches!(x.own_shape(), Shape::Mesh(_)))
        {
            self.next()?;
            return Ok(*o);
        }
        let mut mesh = Mesh::default();
        loop {
            let tok = self.peek()?;
            match tok.ident() {
                Some(w @ ("triangle" | "smooth_triangle")) => {
                    self.mesh_triangle(&mut mesh, w == "smooth_triangle", &tok)?;
                }
                Some("inside_vector") => {
                    self.next()?;
                    mesh.inside_vector = Some(self.inside_vector()?);
                }
                Some("hierarchy") => {
                    self.next()?;
                    self.optional_bool()?;
                }
                _ => break,
            }
        }
        if mesh.faces.is_empty() {
            return Err(self.err(kw.span, "this mesh has no (non-degenerate) triangles"));
        }
        Ok(shape(Shape::Mesh(Box::new(mesh))))
    }

    fn inside_vector(&mut self) -> R<DVec3> {
        let (v, s) = self.expr()?;
        let v = self.to_vec3(&v, s)?;
        if v.length() < 1e-12 {
            return Err(self.err(s, "the inside_vector has zero length"));
        }
        Ok(v)
    }

    /// One `triangle { a, b, c [uv_vectors ...] [texture {...}] }` of a mesh (or smooth).
    fn mesh_triangle(&mut self, mesh: &mut Mesh, smooth: bool, tok: &Token) -> R<()> {
        let word = if smooth {
            "smooth_triangle"
        } else {
            "triangle"
        };
        let open = self.block_start(word)?;
        let (items, flat) = self.triangle_items(smooth)?;
        let (corners, normals) = (items.corners, items.normals.unwrap_or_default());
        let mut uvs = None;
        let mut texture = None;
        loop {
            let t = self.peek()?;
            match t.ident() {
                _ if t.is_punct(Punct::RBrace) => break,
                Some("uv_vectors") => {
                    self.next()?;
                    uvs = Some(self.uv_triple()?);
                }
                Some("texture") => {
                    self.next()?;
                    texture = Some(self.texture_body(self.default_texture.clone())?);
                }
                _ => return Err(self.stray_in_block(&t, "the mesh triangle")),
            }
        }
        self.block_end(open, "the mesh triangle")?;
        self.count_objects(1, std::mem::size_of::<MeshFace>() + 72, tok.span)?;
        if flat {
            return Ok(());
        }
        let base = mesh.vertices.len() as u32;
        let three = [base, base + 1, base + 2];
        mesh.vertices.extend(corners);
        let normals = smooth.then(|| {
            mesh.normals.extend(normals);
            [0, 1, 2].map(|i| mesh.normals.len() as u32 - 3 + i)
        });
        let uvs = uvs.map(|uv: [DVec2; 3]| {
            mesh.uvs.extend(uv);
            [0, 1, 2].map(|i| mesh.uvs.len() as u32 - 3 + i)
        });
        let textures = texture.map(|t| [mesh_texture(mesh, t); 3]);
        mesh.faces.push(MeshFace {
            vertices: three,
            normals,
            uvs,
            textures,
        });
        Ok(())
    }

    fn uv_triple(&mut self) -> R<[DVec2; 3]> {
        let mut uv = [DVec2::ZERO; 3];
        for (i, slot) in uv.iter_mut().enumerate() {
            if i > 0 {
                self.eat(Punct::Comma)?;
            }
            *slot = self.vector3()?.truncate();
        }
        Ok(uv)
    }
}

/// The slot of a texture among the mesh's, reusing the last one when equal (a mesh
/// written by a program repeats the same texture on run after run of triangles).
fn mesh_texture(mesh: &mut Mesh, t: Texture) -> u32 {
    if mesh.textures.last().is_none_or(|last| **last != t) {
        mesh.textures.push(Arc::new(t));
    }
    mesh.textures.len() as u32 - 1
}

impl Evaluator<'_> {
    /// `mesh2 { vertex_vectors {...} normal_vectors {...} uv_vectors {...} texture_list
    /// {...} face_indices {...} normal_indices {...} uv_indices {...} inside_vector v }`.
    /// Lists name what came before them, in POV-Ray's order; without normal_indices (or
    /// uv_indices) the face indices name the normals (or uvs), which then pair with the
    /// vertices one to one.
    pub(super) fn mesh2_items(&mut self, kw: &Token) -> R<ObjectValue> {
        let mut mesh = Mesh::default();
        let mut faces: Option<FaceList> = None;
        let (mut normal_indices, mut uv_indices) = (None, None);
        loop {
            let tok = self.peek()?;
            let Some(word) = tok.ident() else { break };
            match word {
                "vertex_vectors" | "normal_vectors" | "uv_vectors" => {
                    if faces.is_some() {
                        return Err(
                            self.err(tok.span, format!("{word} must come before face_indices"))
                        );
                    }
                    let list = self.vector_list(word)?;
                    match word {
                        "vertex_vectors" => mesh.vertices = list,
                        "normal_vectors" => mesh.normals = list,
                        _ => mesh.uvs = list.iter().map(|v| v.truncate()).collect(),
                    }
                }
                "texture_list" => mesh.textures = self.texture_list()?,
                "face_indices" => faces = Some(self.face_indices(&mesh)?),
                "normal_indices" | "uv_indices" => {
                    let Some(f) = &faces else {
                        return Err(
                            self.err(tok.span, format!("{word} must come after face_indices"))
                        );
                    };
                    let (list, len) = if word == "normal_indices" {
                        ("normal_vectors", mesh.normals.len())
                    } else {
                        ("uv_vectors", mesh.uvs.len())
                    };
                    let idx = self.index_list(word, f.faces.len(), list, len)?;
                    if word == "normal_indices" {
                        normal_indices = Some(idx);
                    } else {
                        uv_indices = Some(idx);
                    }
                }
                "inside_vector" => {
                    self.next()?;
                    mesh.inside_vector = Some(self.inside_vector()?);
                }
                "hierarchy" => {
                    self.next()?;
                    self.optional_bool()?;
                }
                _ => break,
            }
        }
        let Some(list) = faces else {
            return Err(self.err(kw.span, "this mesh2 has no face_indices"));
        };
        self.mesh2_faces(&mut mesh, list, normal_indices, uv_indices, kw.span)?;
        Ok(shape(Shape::Mesh(Box::new(mesh))))
    }

    /// Joins the index lists into faces, checks the implied pairings, drops degenerate
    /// faces.
    fn mesh2_faces(
        &mut self,
        mesh: &mut Mesh,
        list: FaceList,
        normals: Option<Vec<[u32; 3]>>,
        uvs: Option<Vec<[u32; 3]>>,
        span: Span,
    ) -> R<()> {
        let implied = |what: &str, len: usize| {
            let n = mesh.vertices.len();
            (len != n).then(|| {
                format!("without {what}_indices the {len} {what}_vectors pair with the {n} vertex_vectors, so their counts must agree")
            })
        };
        if normals.is_none()
            && !mesh.normals.is_empty()
            && let Some(m) = implied("normal", mesh.normals.len())
        {
            return Err(self.err(span, m));
        }
        if uvs.is_none()
            && !mesh.uvs.is_empty()
            && let Some(m) = implied("uv", mesh.uvs.len())
        {
            return Err(self.err(span, m));
        }
        let has_normals = !mesh.normals.is_empty();
        let has_uvs = !mesh.uvs.is_empty();
        for (i, mut face) in list.faces.into_iter().enumerate() {
            if has_normals {
                face.normals = Some(normals.as_ref().map_or(face.vertices, |n| n[i]));
            }
            if has_uvs {
                face.uvs = Some(uvs.as_ref().map_or(face.vertices, |u| u[i]));
            }
            let corners = face.vertices.map(|v| mesh.vertices[v as usize]);
            if !degenerate(&corners) {
                mesh.faces.push(face);
            }
        }
        if mesh.faces.is_empty() {
            return Err(self.err(span, "this mesh2 has no (non-degenerate) faces"));
        }
        Ok(())
    }

    /// `{ n, v1, v2, ... }`: exactly n vectors.
    fn vector_list(&mut self, word: &str) -> R<Vec<DVec3>> {
        self.next()?;
        let open = self.expect(Punct::LBrace, &format!("after `{word}`"))?;
        self.enter(open.span)?;
        let r = (|| -> R<Vec<DVec3>> {
            let n = self.list_count(word)?;
            self.count_objects(n as u64, 24, open.span)?;
            let mut out = Vec::with_capacity(n.min(1 << 20));
            for i in 0..n {
                self.eat(Punct::Comma)?;
                self.list_item_expected(word, i, n)?;
                out.push(self.vector3()?);
            }
            self.list_end(word, n)?;
            Ok(out)
        })();
        self.leave();
        let out = r?;
        self.expect(Punct::RBrace, &format!("to close {word}"))?;
        Ok(out)
    }

    /// The count that opens a list; it stops before a `<`, which starts the first vector
    /// when the comma after the count is left out (`vertex_vectors { 14 <-1, -1, -1>`).
    fn list_count(&mut self, word: &str) -> R<usize> {
        let s = self.peek()?.span;
        let n = self.map_value()?;
        if !(0.0..=1e8).contains(&n) || n.fract() != 0.0 {
            return Err(self.err(s, format!("{word} needs a whole count, found {n}")));
        }
        Ok(n as usize)
    }

    /// The error for a list that ends before its count.
    fn list_item_expected(&mut self, word: &str, i: usize, n: usize) -> R<()> {
        let t = self.peek()?;
        if t.is_punct(Punct::RBrace) {
            return Err(self.err(
                t.span,
                format!("{word} ends after {i} entries, but its count says {n}"),
            ));
        }
        Ok(())
    }

    /// The error for a list longer than its count.
    fn list_end(&mut self, word: &str, n: usize) -> R<()> {
        self.eat(Punct::Comma)?;
        let t = self.peek()?;
        if !t.is_punct(Punct::RBrace) {
            return Err(self.err(
                t.span,
                format!("{word} has more entries than its count ({n})"),
            ));
        }
        Ok(())
    }

    /// `texture_list { n, texture {...} ... }`.
    fn texture_list(&mut self) -> R<Vec<Arc<Texture>>> {
        let word = "texture_list";
        self.next()?;
        let open = self.expect(Punct::LBrace, "after `texture_list`")?;
        self.enter(open.span)?;
        let r = (|| -> R<Vec<Arc<Texture>>> {
            let n = self.list_count(word)?;
            let mut out = Vec::with_capacity(n.min(1 << 16));
            for i in 0..n {
                self.eat(Punct::Comma)?;
                self.list_item_expected(word, i, n)?;
                let t = self.peek()?;
                if !t.is_ident("texture") {
                    return Err(self.expected("`texture`", &t));
                }
                self.next()?;
                let tex = self.texture_body(self.default_texture.clone())?;
                out.push(self.share_texture(tex));
            }
            self.list_end(word, n)?;
            Ok(out)
        })();
        self.leave();
        let out = r?;
        self.expect(Punct::RBrace, "to close texture_list")?;
        Ok(out)
    }

    /// A vector of three indices into a list of `len` (`what`), checked.
    fn index_triple(&mut self, what: &str, len: usize) -> R<([u32; 3], Span)> {
        let (v, s) = self.expr()?;
        self.triple_of(&v, s, what, len)
    }

    fn triple_of(&self, v: &Value, s: Span, what: &str, len: usize) -> R<([u32; 3], Span)> {
        let Value::Vector(_) = v else {
            return Err(self.err(
                s,
                format!(
                    "expected a vector of three indices, found {}",
                    v.kind_name()
                ),
            ));
        };
        let v = self.to_vec3(v, s)?;
        let mut out = [0u32; 3];
        for (slot, x) in out.iter_mut().zip(v.to_array()) {
            *slot = self.index(x, what, len, s)?;
        }
        Ok((out, s))
    }

    fn index(&self, x: f64, what: &str, len: usize, s: Span) -> R<u32> {
        if x < 0.0 || x.fract() != 0.0 || x >= len as f64 {
            let range = if len == 0 {
                "none".to_string()
            } else {
                format!("0 to {}", len - 1)
            };
            return Err(self.err(
                s,
                format!("index {x} is out of range: {what} has {len} entries ({range})"),
            ));
        }
        Ok(x as u32)
    }

    /// `face_indices { n, <a, b, c> [, t | , t0, t1, t2] ... }`: one texture index gives
    /// the face a texture, three give each corner its own. A value after a face is a
    /// texture index if it is a float, else the next face.
    fn face_indices(&mut self, mesh: &Mesh) -> R<FaceList> {
        let word = "face_indices";
        self.next()?;
        let open = self.expect(Punct::LBrace, "after `face_indices`")?;
        self.enter(open.span)?;
        let r = (|| -> R<FaceList> {
            let n = self.list_count(word)?;
            self.count_objects(n as u64, std::mem::size_of::<MeshFace>(), open.span)?;
            let mut list = FaceList {
                faces: Vec::with_capacity(n.min(1 << 20)),
            };
            let mut pending: Option<(Value, Span)> = None;
            for i in 0..n {
                let (v, s) = match pending.take() {
                    Some(p) => p,
                    None => {
                        self.eat(Punct::Comma)?;
                        self.list_item_expected(word, i, n)?;
                        self.expr()?
                    }
                };
                let (vertices, _) = self.triple_of(&v, s, "vertex_vectors", mesh.vertices.len())?;
                let (textures, next) = self.face_textures(mesh.textures.len())?;
                pending = next;
                list.faces.push(MeshFace {
                    vertices,
                    normals: None,
                    uvs: None,
                    textures,
                });
            }
            if let Some((_, s)) = pending {
                return Err(self.err(s, format!("{word} has more entries than its count ({n})")));
            }
            self.list_end(word, n)?;
            Ok(list)
        })();
        self.leave();
        let list = r?;
        self.expect(Punct::RBrace, "to close face_indices")?;
        Ok(list)
    }

    /// The texture indices after a face's vertex indices, and the next face's value if
    /// reading them met it.
    #[allow(clippy::type_complexity)]
    fn face_textures(&mut self, len: usize) -> R<(Option<[u32; 3]>, Option<(Value, Span)>)> {
        let mut found = Vec::new();
        let mut next = None;
        let mut last = None;
        while found.len() < 3 {
            self.eat(Punct::Comma)?;
            if self.peek()?.is_punct(Punct::RBrace) {
                break;
            }
            let (v, s) = self.expr()?;
            let Value::Float(x) = v else {
                next = Some((v, s));
                break;
            };
            found.push(self.index(x, "texture_list", len, s)?);
            last = Some(s);
        }
        let textures = match found.len() {
            0 => None,
            1 => Some([found[0]; 3]),
            3 => Some([found[0], found[1], found[2]]),
            k => {
                let s = last.unwrap_or(self.peek()?.span);
                return Err(self.err(
                    s,
                    format!("a face takes one or three texture indices, found {k}"),
                ));
            }
        };
        Ok((textures, next))
    }

    /// `normal_indices { n, <a, b, c> ... }` or `uv_indices`: one per face.
    fn index_list(&mut self, word: &str, faces: usize, what: &str, len: usize) -> R<Vec<[u32; 3]>> {
        let tok = self.next()?;
        let open = self.expect(Punct::LBrace, &format!("after `{word}`"))?;
        self.enter(open.span)?;
        let r = (|| -> R<Vec<[u32; 3]>> {
            let n = self.list_count(word)?;
            if n != faces {
                return Err(self.err(
                    tok.span,
                    format!("{word} lists {n} faces, but face_indices has {faces}"),
                ));
            }
            let mut out = Vec::with_capacity(n.min(1 << 20));
            for i in 0..n {
                self.eat(Punct::Comma)?;
                self.list_item_expected(word, i, n)?;
                out.push(self.index_triple(what, len)?.0);
            }
            self.list_end(word, n)?;
            Ok(out)
        })();
        self.leave();
        let out = r?;
        self.expect(Punct::RBrace, &format!("to close {word}"))?;
        Ok(out)
    }
}

impl Evaluator<'_> {
    /// `bicubic_patch { type t [flatness f] [u_steps n] [v_steps m] [uv_vectors c0, c1,
    /// c2, c3] p1, ..., p16 }` up to the object modifiers. The numbers before the points
    /// stop before a `<`, which starts the first point rather than a comparison (as in
    /// POV-Ray: `v_steps 1 <0, 0, 0>`); uv_vectors come before the points, as POV-Ray
    /// requires.
    pub(super) fn bicubic_items(&mut self, kw: &Token) -> R<ObjectValue> {
        let mut patch = BicubicPatch {
            kind: 0,
            flatness: 0.0,
            u_steps: 0,
            v_steps: 0,
            points: [DVec3::ZERO; 16],
            uv: [
                DVec2::new(0.0, 0.0),
                DVec2::new(1.0, 0.0),
                DVec2::new(1.0, 1.0),
                DVec2::new(0.0, 1.0),
            ],
        };
        let mut has_type = false;
        loop {
            let tok = self.peek()?;
            match tok.ident() {
                Some("type") => {
                    self.next()?;
                    let s = self.peek()?.span;
                    let t = self.map_value()?;
                    if t != 0.0 && t != 1.0 {
                        return Err(
                            self.err(s, format!("a bicubic_patch's type is 0 or 1, found {t}"))
                        );
                    }
                    patch.kind = t as u32;
                    has_type = true;
                }
                Some("flatness") => {
                    self.next()?;
                    patch.flatness = self.map_value()?;
                }
                Some("uv_vectors") => {
                    self.next()?;
                    for (i, slot) in patch.uv.iter_mut().enumerate() {
                        if i > 0 {
                            self.eat(Punct::Comma)?;
                        }
                        *slot = self.vector3()?.truncate();
                    }
                }
                Some(w @ ("u_steps" | "v_steps")) => {
                    self.next()?;
                    let s = self.peek()?.span;
                    let n = self.map_value()?;
                    if !(0.0..=crate::geometry::BICUBIC_MAX_STEPS as f64).contains(&n) {
                        return Err(self.err(
                            s,
                            format!(
                                "{w} must be from 0 to {}, found {n}",
                                crate::geometry::BICUBIC_MAX_STEPS
                            ),
                        ));
                    }
                    if w == "u_steps" {
                        patch.u_steps = n as u32;
                    } else {
                        patch.v_steps = n as u32;
                    }
                }
                _ => break,
            }
        }
        if !has_type {
            return Err(self.err(kw.span, "a bicubic_patch needs its `type` (0 or 1)"));
        }
        for i in 0..16 {
            // A comma may follow the last option too (`v_steps 4, <0, 0, 0>, ...`).
            self.eat(Punct::Comma)?;
            let t = self.peek()?;
            if t.is_punct(Punct::RBrace) {
                return Err(self.err(
                    t.span,
                    format!("a bicubic_patch has 16 control points, found {i}"),
                ));
            }
            patch.points[i] = self.vector3()?;
        }
        Ok(shape(Shape::BicubicPatch(Box::new(patch))))
    }
}
