//! `mesh_camera { rays distribution [max_distance] mesh { } ... [smooth] }` inside a camera
//! block, with POV-Ray 3.7's checks (its messages measured: rays per pixel may not be 0,
//! must be <= the number of meshes for type 0, must be 1 for types 2 and 3; the type must
//! be 0 to 3). The meshes are cameras only, never objects of the scene.

use std::sync::Arc;

use super::super::diagnostics::Diagnostic;
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use crate::scene::{
    CameraFace, CameraMesh, MeshCamera, MeshDistribution, Object, Shape, Transform,
};

type R<T> = Result<T, Diagnostic>;

impl Evaluator<'_> {
    /// The block after `mesh_camera`, at the keyword.
    pub(super) fn mesh_camera_block(&mut self, kw: &Token) -> R<MeshCamera> {
        let open = self.block_start("mesh_camera")?;
        let rays_tok = self.peek()?;
        let rays = self.float()?;
        if rays.is_nan() || rays < 1.0 {
            return Err(self.err(
                rays_tok.span,
                format!("mesh_camera: rays per pixel is {rays}; it must be at least 1"),
            ));
        }
        self.eat(Punct::Comma)?;
        let type_tok = self.peek()?;
        let number = self.float()?;
        let Some(distribution) = MeshDistribution::from_number(number) else {
            return Err(self.err(
                type_tok.span,
                format!("mesh_camera: distribution type {number} is not 0, 1, 2 or 3"),
            ));
        };
        self.eat(Punct::Comma)?;
        let mut rig = MeshCamera {
            rays_per_pixel: rays as u32,
            distribution,
            max_distance: None,
            meshes: Vec::new(),
            smooth: false,
        };
        let next = self.peek()?;
        let is_item = next.ident().is_some_and(|w| {
            w == "smooth" || super::objects::is_object_keyword(w) || w == "object"
        });
        if !next.is_punct(Punct::RBrace) && !is_item {
            let d = self.float()?;
            if d > 0.0 {
                rig.max_distance = Some(d);
            }
        }
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            match tok.ident() {
                Some("smooth") => {
                    self.next()?;
                    rig.smooth = true;
                }
                Some("mesh" | "mesh2") => {
                    let value = self.object()?;
                    let mesh =
                        value.object.as_ref().and_then(camera_mesh).ok_or_else(|| {
                            self.err(tok.span, "mesh_camera: this mesh has no faces")
                        })?;
                    if distribution == MeshDistribution::UvMapped
                        && mesh.faces.iter().all(|f| f.uvs.is_none())
                    {
                        return Err(self.err(
                            tok.span,
                            "mesh_camera: distribution type 3 looks pixels up in the uv map, and this mesh has no uv_vectors",
                        ));
                    }
                    rig.meshes.push(mesh);
                }
                Some(w) if super::objects::is_object_keyword(w) || w == "object" => {
                    return Err(self.err(
                        tok.span,
                        format!(
                            "mesh_camera: only mesh and mesh2 objects can be cameras, found `{w}`"
                        ),
                    ));
                }
                _ => return Err(self.stray_in_block(&tok, "the mesh_camera")),
            }
        }
        let what = "the mesh_camera";
        if rig.meshes.is_empty() {
            return Err(self.err(kw.span, "mesh_camera: no mesh { } to shoot rays from"));
        }
        let limit = |message: &str| Err(self.err(rays_tok.span, format!("mesh_camera: {message}")));
        match distribution {
            MeshDistribution::PerMesh if rig.rays_per_pixel as usize > rig.meshes.len() => {
                return limit(&format!(
                    "rays per pixel ({}) must be at most the number of meshes ({}) for distribution type 0",
                    rig.rays_per_pixel,
                    rig.meshes.len()
                ));
            }
            MeshDistribution::SideBySide | MeshDistribution::UvMapped
                if rig.rays_per_pixel != 1 =>
            {
                return limit("rays per pixel must be 1 for distribution types 2 and 3");
            }
            _ => {}
        }
        self.block_end(open, what)?;
        Ok(rig)
    }
}

/// A mesh object's faces in world space; `None` for other shapes and empty meshes.
fn camera_mesh(o: &Object) -> Option<CameraMesh> {
    if let Shape::Instance(_) = o.shape {
        let mut own = o.clone();
        own.unshared();
        return camera_mesh(&own);
    }
    let Shape::Mesh(m) = &o.shape else {
        return None;
    };
    let t: &Transform = &o.transform;
    let faces: Vec<CameraFace> = m
        .faces
        .iter()
        .map(|f| CameraFace {
            corners: f.vertices.map(|i| t.point(m.vertices[i as usize])),
            normals: f
                .normals
                .map(|ns| ns.map(|i| t.normal(m.normals[i as usize]))),
            uvs: f.uvs.map(|us| us.map(|i| m.uvs[i as usize])),
        })
        .collect();
    (!faces.is_empty()).then_some(CameraMesh { faces })
}

/// Keeps the rig shared between cameras that copy it.
pub(super) fn shared(rig: MeshCamera) -> Arc<MeshCamera> {
    Arc::new(rig)
}
