//! The render-ready scene: the scene model turned into primitives with world-space
//! transforms, CSG nodes and a BVH, each primitive pointing at its material, plus lights
//! prepared for sampling.

use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;

use glam::{DAffine3, DVec2, DVec3};

use crate::appearance::may_transmit;
use crate::geometry::{
    BicubicSubdivision, BlobData, BlobPart, CsgOp, HeightFieldData, Item, JuliaData, LatheData,
    MeshData, NO_INDEX, OWN_TEXTURE, PolyData, PolygonData, PrismData, ShapeKind, SorData,
    Superellipsoid, Transform, TriangleData, World, WorldBuilder, flags, tessellate_bicubic,
};
use crate::scene::{
    BicubicPatch, Blob, BlobComponentKind, Camera, Colour, GlobalSettings, Interior, Mesh,
    MeshFace, Object, ObjectFlags, Scene, Shape, SkySphere, Texture,
};

use super::dimensions::{DimensionLayout, OptionalDecisions};
use super::lights::PreparedLight;
use super::media::MediaTable;

/// How the traced values of a scene computed in gamma space become linear light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GammaDecode {
    Srgb,
    Power(f64),
}

impl GammaDecode {
    pub fn decode(self, c: f64) -> f64 {
        let c = c.max(0.0);
        match self {
            GammaDecode::Srgb => crate::output::srgb::decode(c),
            // 2^(g log2 c): a sample decodes three channels, and `powf` took 13% of
            // incdemo/stones/pinkmarb's instructions (240 a call against 90); the relative
            // error, about |g log2 c| 2^-52, is 1e-14 at c = 10^-6.
            GammaDecode::Power(g) => (g * c.log2()).exp2(),
        }
    }
}

#[derive(Clone, Debug)]
pub struct Material {
    /// Shared with the scene model and with every other material of the same texture.
    pub texture: Arc<Texture>,
    pub double_illuminate: bool,
    /// Whether the texture lets light through anywhere (else shadow rays stop here).
    pub transmits: bool,
    pub interior: Interior,
    /// Which interior this is: the parts of one object given an `interior` share it, as in
    /// POV-Ray, where a ray inside that interior that meets any of its parts leaves it.
    pub interior_id: u32,
    /// `hollow`: fog goes on inside the object.
    pub hollow: bool,
    /// Which lights shade it (`scene::LightGroup`).
    pub light_group: Option<crate::scene::LightGroup>,
    /// With an `interior_texture`: the material (this one with that texture) of the inner
    /// side, seen by rays that meet the surface going along its outward normal.
    pub inner: Option<u32>,
    /// How photons treat it (`photons { }`; the defaults where it has none).
    pub photons: crate::scene::ObjectPhotons,
    /// A photon target photons meet (not `no_shadow` or `no_image`) in a scene with
    /// photons: the shadow rays of some lights may stop here, as the photons bring their
    /// light through it (`ObjectPhotons::stops_shadows`).
    pub photon_shadow: bool,
}

#[derive(Clone, Debug)]
pub struct PreparedScene {
    pub world: World,
    pub materials: Vec<Material>,
    pub lights: Vec<PreparedLight>,
    pub camera: Camera,
    /// A mesh camera's faces and side tables (src/render/mesh_camera.rs).
    pub mesh_camera: Option<super::mesh_camera::MeshCameraRays>,
    /// How far camera rays reach (a mesh camera's `max_distance`; else unbounded).
    pub camera_reach: f64,
    pub background: Colour,
    pub sky_sphere: Option<SkySphere>,
    /// The fogs that apply (distance > 0).
    pub fogs: Vec<crate::scene::Fog>,
    pub rainbows: Vec<crate::scene::Rainbow>,
    /// The atmospheric media and those of every interior.
    pub media: MediaTable,
    pub settings: GlobalSettings,
    pub legacy: bool,
    /// Scenes with `assumed_gamma g` (g != 1), and pre-3.7 scenes without one, are computed
    /// in gamma space; POV-Ray 3.7 then writes linear files by decoding each traced value,
    /// with the power g, or the sRGB curve for old scenes without assumed_gamma (measured).
    pub output_gamma: Option<GammaDecode>,
    /// Whether any material lets light through: if none does, shadow rays only ask
    /// whether anything is in the way.
    pub any_transmitting: bool,
}

impl PreparedScene {
    /// Which sampler dimension each decision reads: it depends on the lights (and the
    /// optional decisions the scene makes), never on the objects.
    pub fn dimension_layout(&self) -> DimensionLayout {
        let optional = OptionalDecisions {
            media: !self.media.is_empty(),
            dispersion: self.materials.iter().any(|m| m.interior.disperses()),
            diffuse: self.settings.radiosity.is_some(),
            ..OptionalDecisions::default()
        };
        DimensionLayout::new(self.lights.len(), optional)
    }

    /// The material a ray sees on the side it meets: the inner one (`interior_texture`)
    /// when it meets the surface from behind, going along the outward normal, as measured
    /// with POV-Ray 3.7 on spheres, open cylinders, planes, discs, polygons and the
    /// cavities a difference leaves.
    pub fn side_material(&self, index: u32, back: bool) -> &Material {
        let material = &self.materials[index as usize];
        match material.inner {
            Some(inner) if back => &self.materials[inner as usize],
            _ => material,
        }
    }

    pub fn new(scene: &Scene) -> PreparedScene {
        let default_texture = Arc::new(Texture::default());
        let mut builder = Builder::new(
            MediaTable::new(&scene.media),
            scene.settings.photons.is_some(),
            default_texture.clone(),
        );
        let on = |f: fn(&crate::scene::LightPhotons) -> Option<bool>| {
            scene
                .lights
                .iter()
                .any(|l| f(&l.photons) == Some(true))
                .then_some(true)
        };
        builder.photon_lights = crate::scene::LightPhotons {
            refraction: on(|p| p.refraction),
            reflection: on(|p| p.reflection),
            ..Default::default()
        };
        let default_interior = Interior::default();
        let looks = Looks::plain(&default_texture, &default_interior);
        let looks_like = scene.lights.iter().filter_map(|l| l.looks_like.as_deref());
        for object in scene.objects.iter().chain(looks_like) {
            builder.object(object, looks, true);
        }
        PreparedScene {
            any_transmitting: builder.materials.iter().any(|m| m.transmits),
            world: builder.world.build(),
            materials: builder.materials,
            media: builder.media,
            lights: scene.lights.iter().map(PreparedLight::new).collect(),
            camera: scene.camera.clone(),
            mesh_camera: scene
                .camera
                .mesh
                .as_ref()
                .map(super::mesh_camera::MeshCameraRays::new),
            camera_reach: scene
                .camera
                .mesh
                .as_ref()
                .and_then(|m| m.rig.max_distance)
                .unwrap_or(f64::INFINITY),
            background: scene.background,
            sky_sphere: scene.sky_sphere.clone(),
            fogs: scene
                .fogs
                .iter()
                .filter(|f| f.distance > 0.0)
                .cloned()
                .collect(),
            rainbows: scene.rainbows.clone(),
            settings: scene.settings.clone(),
            legacy: scene.legacy(),
            output_gamma: match (scene.legacy(), scene.settings.assumed_gamma) {
                (true, None) => Some(GammaDecode::Srgb),
                (_, Some(g)) if (g - 1.0).abs() > 1e-9 && g > 0.0 => Some(GammaDecode::Power(g)),
                _ => None,
            },
        }
    }
}

/// The interior-owner key of the default interior that opaque primitives share.
const OPAQUE_INTERIOR: usize = usize::MAX;

/// What makes two primitives' materials the same. Their textures are compared by address
/// (the evaluator already shares equal textures of consecutive objects). A primitive with
/// the default interior that light can pass has one of its own, since a ray inside it must
/// leave it at its own surface: it gets no key.
#[derive(PartialEq, Eq, Hash)]
struct MaterialKey {
    texture: usize,
    interior_texture: usize,
    interior_owner: usize,
    double_illuminate: bool,
    hollow: bool,
    light_group: Option<(u32, bool)>,
    photons: crate::scene::ObjectPhotons,
}

impl MaterialKey {
    fn of(looks: Looks<'_>) -> Option<MaterialKey> {
        let opaque = looks.interior_texture.is_none() && !may_transmit(looks.texture);
        let interior_owner = match looks.interior_owner {
            Some(owner) => owner,
            None if opaque => OPAQUE_INTERIOR,
            None => return None,
        };
        let f = looks.flags;
        Some(MaterialKey {
            texture: Arc::as_ptr(looks.texture) as usize,
            interior_texture: looks
                .interior_texture
                .map_or(0, |t| Arc::as_ptr(t) as usize),
            interior_owner,
            double_illuminate: f.double_illuminate,
            hollow: f.hollow,
            light_group: f.light_group.map(|g| (g.id, g.global_lights)),
            photons: f.photons.unwrap_or_default(),
        })
    }
}

struct Builder {
    world: WorldBuilder,
    materials: Vec<Material>,
    /// The materials primitives share, by what they hold.
    shared: HashMap<MaterialKey, u32>,
    /// Interior ids by owner (see Looks::interior_owner).
    interior_ids: HashMap<usize, u32>,
    media: MediaTable,
    /// Whether the scene computes caustics with photons (global_settings photons).
    photons: bool,
    /// What some light's photons block turns on (`Some(true)`) for targets that say
    /// nothing themselves (see [`crate::scene::ObjectPhotons::refracts`]).
    photon_lights: crate::scene::LightPhotons,
    /// The texture of objects without one, by address: an instance inherits nothing only
    /// if its looks hold this one.
    default_texture: Arc<Texture>,
    /// The prototypes built so far, by the shared object's address (`None`: it is copied
    /// instead, see [`Builder::prototype`]).
    prototypes: HashMap<usize, Option<Rc<Prototype>>>,
    /// Building a prototype: instances in it are copied (a prototype holds none).
    in_prototype: bool,
}

/// A shared object's geometry and materials, built once. Each placement takes a copy of
/// the materials with their textures moved into place (textures are evaluated in world
/// space), numbered after the scene's.
struct Prototype {
    world: Arc<World>,
    materials: Vec<Material>,
    /// The interior its opaque materials share.
    opaque_interior: Option<u32>,
}

fn combine(f: ObjectFlags, inherited: ObjectFlags) -> ObjectFlags {
    ObjectFlags {
        no_shadow: f.no_shadow || inherited.no_shadow,
        no_image: f.no_image || inherited.no_image,
        no_reflection: f.no_reflection || inherited.no_reflection,
        hollow: f.hollow || inherited.hollow,
        inverse: f.inverse,
        double_illuminate: f.double_illuminate || inherited.double_illuminate,
        light_group: f.light_group.or(inherited.light_group),
        no_radiosity: f.no_radiosity || inherited.no_radiosity,
        photons: f.photons.or(inherited.photons),
    }
}

/// A texture moved by a placement: a copy, unless it is the same everywhere.
fn moved(texture: &Arc<Texture>, t: &Transform) -> Arc<Texture> {
    fn uniform(t: &Texture) -> bool {
        t.map.is_none()
            && t.normal.is_none()
            && matches!(t.pigment.kind, crate::scene::PigmentKind::Solid(_))
            && t.below.iter().all(uniform)
    }
    if t.is_identity() || uniform(texture) {
        return texture.clone();
    }
    let mut copy = (**texture).clone();
    copy.transform_by(t);
    Arc::new(copy)
}

/// The frame that takes the unit z axis to `from -> to` without scaling x and y.
fn axis_frame(from: DVec3, to: DVec3) -> Option<Transform> {
    let axis = to - from;
    let len = axis.length();
    if len.is_nan() || len <= 0.0 || !len.is_finite() {
        return None;
    }
    let w = axis / len;
    let (u, v) = w.any_orthonormal_pair();
    Transform::from_affine(DAffine3::from_cols(u, v, axis, from))
}

/// A blob's components in their canonical frames (radius 1; a cylinder along z from its
/// first end), bounded by the components that add to the field.
fn iso_data(iso: &crate::scene::Isosurface) -> crate::geometry::IsoData {
    crate::geometry::IsoData {
        function: iso.function.clone(),
        container: iso.container,
        threshold: iso.threshold,
        accuracy: iso.accuracy,
        max_gradient: iso.max_gradient,
        open: iso.open,
        steepest: Default::default(),
        origin: iso.origin.clone(),
    }
}

/// The blob's field, with `materials[i]` the material of component i (`NONE`: the blob's).
fn blob_data(blob: &Blob, materials: &[u32]) -> Option<BlobData> {
    let mut parts = Vec::with_capacity(blob.components.len());
    for (c, &material) in blob.components.iter().zip(materials) {
        let r = c.radius.abs();
        if r <= 0.0 || !r.is_finite() {
            continue;
        }
        let (frame, length) = match c.kind {
            BlobComponentKind::Sphere { center } => (
                DAffine3::from_translation(center) * DAffine3::from_scale(DVec3::splat(r)),
                0.0,
            ),
            BlobComponentKind::Cylinder { end1, end2 } => {
                let axis = end2 - end1;
                let len = axis.length();
                if len.is_nan() || len <= 0.0 || !len.is_finite() {
                    continue;
                }
                let w = axis / len;
                let (u, v) = w.any_orthonormal_pair();
                (DAffine3::from_cols(u * r, v * r, w * r, end1), len / r)
            }
        };
        let forward = c.transform.forward * frame;
        let to_local = Transform::from_affine(forward)?.inverse;
        parts.push(BlobPart {
            to_local,
            strength: c.strength,
            length,
            material,
        });
    }
    Some(BlobData::new(blob.threshold, parts))
}

/// What a CSG child inherits from its parents: texture, interior and flags.
#[derive(Clone, Copy)]
struct Looks<'a> {
    texture: &'a Arc<Texture>,
    interior_texture: Option<&'a Arc<Texture>>,
    interior: &'a Interior,
    /// The object whose `interior` this is (its address), or None for the default one,
    /// which every primitive has to itself.
    interior_owner: Option<usize>,
    flags: ObjectFlags,
}

impl<'a> Looks<'a> {
    /// What a top-level object inherits: the default texture and interior, no flags.
    fn plain(texture: &'a Arc<Texture>, interior: &'a Interior) -> Looks<'a> {
        Looks {
            texture,
            interior_texture: None,
            interior,
            interior_owner: None,
            flags: ObjectFlags::default(),
        }
    }
}

impl Builder {
    fn new(media: MediaTable, photons: bool, default_texture: Arc<Texture>) -> Builder {
        Builder {
            world: WorldBuilder::default(),
            materials: Vec::new(),
            shared: HashMap::new(),
            interior_ids: HashMap::new(),
            media,
            photons,
            photon_lights: crate::scene::LightPhotons::default(),
            default_texture,
            prototypes: HashMap::new(),
            in_prototype: false,
        }
    }

    /// Adds an object; at the top level, unions dissolve into their children so the BVH sees
    /// each part. Returns the item for use as a CSG child.
    fn object(&mut self, object: &Object, inherited: Looks<'_>, top: bool) -> Option<Item> {
        let looks = Looks {
            texture: object.texture.as_ref().unwrap_or(inherited.texture),
            interior_texture: object
                .interior_texture
                .as_ref()
                .or(inherited.interior_texture),
            interior: object.interior.as_deref().unwrap_or(inherited.interior),
            interior_owner: match object.interior.as_deref() {
                Some(i) => Some(i as *const Interior as usize),
                None => inherited.interior_owner,
            },
            flags: combine(object.flags, inherited.flags),
        };
        let f = looks.flags;
        let clipped = !object.clipped_by().is_empty();
        let group_at_top = top && !f.inverse && !clipped;
        let item = match &object.shape {
            Shape::Union(children) if group_at_top => {
                for child in children {
                    self.object(child, looks, true);
                }
                return None;
            }
            Shape::Union(children)
            | Shape::Merge(children)
            | Shape::Intersection(children)
            | Shape::Difference(children) => self.csg(&object.shape, children, looks)?,
            Shape::Mesh(mesh) => self.mesh(mesh, object, looks)?,
            Shape::Instance(shared) => match self.placed(shared, object, looks) {
                Some(item) => item,
                None => {
                    let mut copy = object.clone();
                    copy.unshared();
                    return self.object(&copy, inherited, top);
                }
            },
            Shape::Triangle(corners) => self.triangle(**corners, None, object, looks)?,
            Shape::SmoothTriangle(t) => self.triangle(t.corners, Some(t.normals), object, looks)?,
            shape => self.primitive(shape, object, looks)?,
        };
        let item = if clipped {
            self.clipped(item, object, looks)
        } else {
            item
        };
        let item = if object.bounded_by().is_empty() {
            item
        } else {
            self.bounded(item, object, looks)
        };
        if top {
            self.world.add_top(item);
            // A target that neither reflects nor refracts any light's photons gets none
            // (POV-Ray: photon time 0.000 s for such a scene), nor does one photons go
            // through.
            let lights = &self.photon_lights;
            if self.photons
                && !(f.no_shadow || f.no_image)
                && f.photons
                    .is_some_and(|p| p.target && (p.reflects(lights) || p.refracts(lights)))
            {
                self.world.add_photon_target(item);
            }
        }
        Some(item)
    }

    /// A shared object placed by `object`'s transform, sharing its prototype's geometry;
    /// `None` where it must be copied instead: it inherits looks from a parent (its
    /// prototype's materials would differ per placement), or the scene shoots photons at
    /// targets (which are top-level items), or the prototype cannot be shared.
    fn placed(&mut self, shared: &Arc<Object>, object: &Object, looks: Looks<'_>) -> Option<Item> {
        let plain = Arc::ptr_eq(looks.texture, &self.default_texture)
            && looks.interior_texture.is_none()
            && looks.interior_owner.is_none()
            && looks.flags == ObjectFlags::default();
        if !plain || self.in_prototype || self.photons {
            return None;
        }
        let prototype = self.prototype(shared)?;
        let first = self.materials.len() as u32;
        let mut interiors = HashMap::new();
        let mut textures: HashMap<usize, Arc<Texture>> = HashMap::new();
        for material in &prototype.materials {
            let mut m = material.clone();
            let key = Arc::as_ptr(&m.texture) as usize;
            m.texture = textures
                .entry(key)
                .or_insert_with(|| moved(&material.texture, &object.transform))
                .clone();
            m.interior_id = if Some(m.interior_id) == prototype.opaque_interior {
                self.interior_of(OPAQUE_INTERIOR)
            } else {
                let fresh = OPAQUE_INTERIOR - 1 - self.materials.len();
                *interiors
                    .entry(m.interior_id)
                    .or_insert_with(|| self.interior_of(fresh))
            };
            m.inner = m.inner.map(|i| i + first);
            self.materials.push(m);
        }
        let world = prototype.world.clone();
        Some(self.world.instance(world, *object.transform, first))
    }

    /// The prototype of a shared object, built on its first placement. `None` where it
    /// cannot be shared: its interiors hold media (their densities are read in world
    /// space per interior), or it has blobs with textured components (whose blend reads
    /// the prototype's own tables).
    fn prototype(&mut self, shared: &Arc<Object>) -> Option<Rc<Prototype>> {
        let key = Arc::as_ptr(shared) as usize;
        if let Some(built) = self.prototypes.get(&key) {
            return built.clone();
        }
        let mut b = Builder::new(MediaTable::new(&[]), false, self.default_texture.clone());
        b.in_prototype = true;
        let texture = self.default_texture.clone();
        let interior = Interior::default();
        let looks = Looks::plain(&texture, &interior);
        b.object(shared, looks, true);
        let world = b.world.build();
        let built = (b.media.is_empty() && !world.has_textured_blobs()).then(|| {
            Rc::new(Prototype {
                world: Arc::new(world),
                materials: b.materials,
                opaque_interior: b.interior_ids.get(&OPAQUE_INTERIOR).copied(),
            })
        });
        self.prototypes.insert(key, built.clone());
        built
    }

    /// The interior id of an owner key, made on first use.
    fn interior_of(&mut self, owner: usize) -> u32 {
        let next = self.interior_ids.len() as u32;
        let id = *self.interior_ids.entry(owner).or_insert(next);
        self.media.add_interior(id, &[]);
        id
    }

    /// A CSG node of `shape`'s kind over its children, which do not inherit `inverse`.
    fn csg(&mut self, shape: &Shape, children: &[Object], looks: Looks<'_>) -> Option<Item> {
        let op = match shape {
            Shape::Union(_) => CsgOp::Union,
            Shape::Merge(_) => CsgOp::Merge,
            Shape::Intersection(_) => CsgOp::Intersection,
            _ => CsgOp::Difference,
        };
        let child_looks = Looks {
            flags: ObjectFlags {
                inverse: false,
                ..looks.flags
            },
            ..looks
        };
        let items: Vec<Item> = children
            .iter()
            .filter_map(|c| self.object(c, child_looks, false))
            .collect();
        if items.is_empty() {
            return None;
        }
        Some(self.world.csg(op, items, looks.flags.inverse))
    }

    /// A single shape with its object's transform (after the shape's own frame).
    fn primitive(&mut self, shape: &Shape, object: &Object, looks: Looks<'_>) -> Option<Item> {
        let (kind, local) = match shape {
            Shape::Blob(blob) => (self.blob(blob, looks)?, None),
            Shape::BicubicPatch(patch) => (self.bicubic(patch, &object.transform)?, None),
            _ => self.shape_kind(shape)?,
        };
        let transform = match local {
            Some(frame) => frame.then(&object.transform),
            None => *object.transform,
        };
        let material = self.material(looks);
        let uv = if looks.texture.uses_uv() {
            flags::UV
        } else {
            0
        };
        Some(
            self.world
                .primitive(kind, &transform, material, mask(looks.flags) | uv),
        )
    }

    /// A mesh as one primitive over its own BVH, with a material per texture its faces
    /// name.
    fn mesh(&mut self, mesh: &Mesh, object: &Object, looks: Looks<'_>) -> Option<Item> {
        let mut data = mesh_data(mesh)?;
        data.materials = mesh
            .textures
            .iter()
            .map(|t| {
                self.material(Looks {
                    texture: t,
                    ..looks
                })
            })
            .collect();
        data.finish();
        let uv = looks.texture.uses_uv() || mesh.textures.iter().any(|t| t.uses_uv());
        self.world.tables.meshes.push(data);
        let kind = ShapeKind::Mesh((self.world.tables.meshes.len() - 1) as u32);
        let material = self.material(looks);
        let flags = mask(looks.flags) | if uv { flags::UV } else { 0 };
        Some(
            self.world
                .primitive(kind, &object.transform, material, flags),
        )
    }

    /// A blob's table entry, with a material for each component's own texture (which
    /// shares the blob's interior and flags).
    fn blob(&mut self, blob: &Blob, looks: Looks<'_>) -> Option<ShapeKind> {
        let materials: Vec<u32> = blob
            .components
            .iter()
            .map(|c| {
                c.texture.as_ref().map_or(OWN_TEXTURE, |t| {
                    self.material(Looks {
                        texture: t,
                        ..looks
                    })
                })
            })
            .collect();
        self.world.tables.blobs.push(blob_data(blob, &materials)?);
        Some(ShapeKind::Blob((self.world.tables.blobs.len() - 1) as u32))
    }

    /// A bicubic patch as a mesh. POV-Ray moves the control points before it cuts the
    /// patch, so `flatness` is a distance in the scene's units: the test sees the net
    /// through the object's transform (objects/bezier.pov, scaled by 2: flatness 0.1 in the
    /// patch's own units is off by sqrt(B) 0.0084, in the scene's it matches POV-Ray).
    fn bicubic(&mut self, patch: &BicubicPatch, transform: &Transform) -> Option<ShapeKind> {
        let mut data = tessellate_bicubic(
            &patch.points,
            BicubicSubdivision {
                along: patch.v_steps,
                across: patch.u_steps,
                flatness: patch.flatness,
                to_scene: transform.forward,
            },
            patch.uv,
        );
        if data.faces.is_empty() {
            return None;
        }
        data.finish();
        let tables = &mut self.world.tables;
        tables.meshes.push(data);
        Some(ShapeKind::Mesh((tables.meshes.len() - 1) as u32))
    }

    /// `item` clipped by the object's `clipped_by` shapes, which keep no flags of their own.
    fn clipped(&mut self, item: Item, object: &Object, looks: Looks<'_>) -> Item {
        let mut parts = vec![item];
        let clip_looks = Looks {
            flags: ObjectFlags::default(),
            ..looks
        };
        for clip in object.clipped_by() {
            parts.extend(self.object(clip, clip_looks, false));
        }
        self.world.csg(CsgOp::Clip, parts, false)
    }

    /// `item` seen only by rays that meet the object's `bounded_by` shapes.
    fn bounded(&mut self, item: Item, object: &Object, looks: Looks<'_>) -> Item {
        let mut parts = vec![item];
        let bound_looks = Looks {
            flags: ObjectFlags::default(),
            ..looks
        };
        for bound in object.bounded_by() {
            parts.extend(self.object(bound, bound_looks, false));
        }
        self.world.csg(CsgOp::Bound, parts, false)
    }

    /// The material for `looks`: shared with every primitive of the same looks where that
    /// is exact (see [`MaterialKey`]), so a million spheres of one texture hold one.
    fn material(&mut self, looks: Looks<'_>) -> u32 {
        let key = MaterialKey::of(looks);
        if let Some(&index) = key.as_ref().and_then(|k| self.shared.get(k)) {
            return index;
        }
        let index = self.new_material(looks, key.is_some());
        if let Some(key) = key {
            self.shared.insert(key, index);
        }
        index
    }

    /// A material not made before; `shared`: others may share it ([`MaterialKey`]), so with
    /// the default interior it is opaque and takes the interior all opaque ones share.
    fn new_material(&mut self, looks: Looks<'_>, shared: bool) -> u32 {
        let interior = looks.interior;
        let owner = match looks.interior_owner {
            Some(owner) => owner,
            // Opaque and with nothing inside: no ray enters, so all share one interior.
            None if shared => OPAQUE_INTERIOR,
            // A default interior of its own: a key no address can take.
            None => OPAQUE_INTERIOR - 1 - self.materials.len(),
        };
        let interior_id = self.interior_of(owner);
        self.media.add_interior(interior_id, &interior.media);
        let photons = looks.flags.photons.unwrap_or_default();
        // POV-Ray's shadow rays stop at a target that refracts photons: the photons bring
        // the light that passes through it (measured: the shadow under a clear glass
        // target is black but for its caustic). Photons go through `no_shadow` and
        // `no_image` objects, and so does the light then (measured: a `no_image` glass
        // target's shadow lets the light through, with no caustic). Light by light
        // (`ObjectPhotons::stops_shadows`): a light whose photons it does not refract keeps
        // the filtered shadow (advanced/optics: the lenses under the light `photons {
        // refraction off reflection off }`).
        let photons_meet = !(looks.flags.no_shadow || looks.flags.no_image);
        self.materials.push(Material {
            texture: looks.texture.clone(),
            double_illuminate: looks.flags.double_illuminate,
            transmits: may_transmit(looks.texture),
            photons,
            photon_shadow: self.photons && photons.target && photons_meet,
            // The media go to the scene's media table, once per interior.
            interior: with_finish_caustics(
                Interior {
                    media: Vec::new(),
                    ..interior.clone()
                },
                looks.texture,
            ),
            interior_id,
            hollow: looks.flags.hollow,
            light_group: looks.flags.light_group,
            inner: None,
        });
        let outer = self.materials.len() - 1;
        if let Some(inside) = looks.interior_texture {
            let mut inner = self.materials[outer].clone();
            inner.texture = inside.clone();
            inner.transmits = may_transmit(inside);
            // Shadow rays ask the outer material whether to look at the surface at all.
            self.materials[outer].transmits |= inner.transmits;
            self.materials[outer].inner = Some(self.materials.len() as u32);
            self.materials.push(inner);
        }
        outer as u32
    }

    /// Triangles are moved into world space at build time: an affine map keeps a triangle
    /// a triangle, which spares a transform per ray.
    fn triangle(
        &mut self,
        corners: [DVec3; 3],
        normals: Option<[DVec3; 3]>,
        object: &Object,
        looks: Looks<'_>,
    ) -> Option<Item> {
        let t = &object.transform;
        let p = corners.map(|c| t.point(c));
        let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
        if e1.cross(e2).length_squared() == 0.0 {
            return None;
        }
        let index = self.world.tables.triangles.len() as u32;
        self.world.tables.triangles.push(TriangleData {
            p0: p[0],
            e1,
            e2,
            normals: normals.map(|n| n.map(|n| t.normal(n).normalize_or(DVec3::Z))),
        });
        let material = self.material(looks);
        Some(self.world.primitive(
            ShapeKind::Triangle(index),
            &Transform::IDENTITY,
            material,
            mask(looks.flags),
        ))
    }

    /// The render shape for a scene shape, with the frame that places its canonical form.
    fn shape_kind(&mut self, shape: &Shape) -> Option<(ShapeKind, Option<Transform>)> {
        Some(match *shape {
            Shape::Sphere { center, radius } => (ShapeKind::Sphere { center, radius }, None),
            Shape::Plane { normal, distance } => (ShapeKind::Plane { normal, distance }, None),
            Shape::Box { corner1, corner2 } => (
                ShapeKind::Box {
                    min: corner1.min(corner2),
                    max: corner1.max(corner2),
                },
                None,
            ),
            Shape::Cylinder(ref c) => (
                ShapeKind::Cone {
                    r0: c.radius,
                    r1: c.radius,
                    open: c.open,
                },
                Some(axis_frame(c.base, c.cap)?),
            ),
            Shape::Cone(ref c) => (
                ShapeKind::Cone {
                    r0: c.base_radius,
                    r1: c.cap_radius,
                    open: c.open,
                },
                Some(axis_frame(c.base, c.cap)?),
            ),
            Shape::Disc(ref d) => (
                ShapeKind::Disc {
                    radius: d.radius,
                    hole: d.hole_radius,
                },
                Some(axis_frame(
                    d.center,
                    d.center + d.normal.normalize_or(DVec3::Y),
                )?),
            ),
            Shape::Torus { major, minor } => (ShapeKind::Torus { major, minor }, None),
            Shape::Quadric(ref coefficients) => {
                self.world.tables.quadrics.push(**coefficients);
                (
                    ShapeKind::Quadric((self.world.tables.quadrics.len() - 1) as u32),
                    None,
                )
            }
            Shape::Quartic { .. } | Shape::Poly { .. } | Shape::Julia(_) => {
                (self.algebraic_shape(shape)?, None)
            }
            Shape::Polygon { ref points } => {
                let (data, frame) = polygon(points)?;
                self.world.tables.polygons.push(data);
                (
                    ShapeKind::Polygon((self.world.tables.polygons.len() - 1) as u32),
                    Some(frame),
                )
            }
            Shape::Prism(_) | Shape::Sor(_) | Shape::Lathe(_) => (self.spline_shape(shape)?, None),
            Shape::Glyph(_) => (self.spline_shape(shape)?, None),
            Shape::Superellipsoid { .. } | Shape::Isosurface(_) => {
                return self.field_shape(shape);
            }
            Shape::HeightField(_) => (self.grid_shape(shape)?, None),
            Shape::Triangle(_)
            | Shape::SmoothTriangle(_)
            | Shape::Blob(_)
            | Shape::BicubicPatch(_)
            | Shape::Mesh(_)
            | Shape::Union(_)
            | Shape::Merge(_)
            | Shape::Intersection(_)
            | Shape::Difference(_)
            | Shape::Instance(_) => return None,
        })
    }

    /// Shapes defined by a field (a function of the point) and its threshold.
    fn field_shape(&mut self, shape: &Shape) -> Option<(ShapeKind, Option<Transform>)> {
        Some(match *shape {
            Shape::Superellipsoid {
                east_west,
                north_south,
            } => (
                ShapeKind::Superellipsoid(Superellipsoid::new(east_west, north_south)),
                None,
            ),
            Shape::Isosurface(ref iso) => {
                self.world.tables.isosurfaces.push(iso_data(iso));
                let i = self.world.tables.isosurfaces.len() - 1;
                (ShapeKind::Isosurface(i as u32), None)
            }
            _ => return None,
        })
    }

    /// The table entry of a height field (`None` for other shapes, or for data that makes
    /// no surface).
    fn grid_shape(&mut self, shape: &Shape) -> Option<ShapeKind> {
        let tables = &mut self.world.tables;
        Some(match shape {
            Shape::HeightField(hf) => {
                let data = HeightFieldData::new(
                    hf.columns,
                    hf.rows,
                    hf.heights.clone(),
                    hf.smooth,
                    hf.water_level,
                )?;
                tables.height_fields.push(data);
                ShapeKind::HeightField((tables.height_fields.len() - 1) as u32)
            }
            _ => return None,
        })
    }

    /// The table entry of a quartic, poly or julia_fractal (`None` for other shapes).
    fn algebraic_shape(&mut self, shape: &Shape) -> Option<ShapeKind> {
        let tables = &mut self.world.tables;
        Some(match *shape {
            Shape::Quartic { ref coefficients } => {
                let mut q = [0.0; 35];
                for (slot, c) in q.iter_mut().zip(coefficients) {
                    *slot = *c;
                }
                tables.quartics.push(q);
                ShapeKind::Quartic((tables.quartics.len() - 1) as u32)
            }
            Shape::Poly {
                order,
                ref coefficients,
            } => {
                tables
                    .polys
                    .push(PolyData::new(order as usize, coefficients));
                ShapeKind::Poly((tables.polys.len() - 1) as u32)
            }
            Shape::Julia(ref julia) => {
                tables.julias.push(JuliaData::new(julia));
                ShapeKind::Julia((tables.julias.len() - 1) as u32)
            }
            _ => return None,
        })
    }

    /// The table entry of a prism (or a text glyph), sor or lathe (`None` for other shapes, or for points
    /// that make no shape).
    fn spline_shape(&mut self, shape: &Shape) -> Option<ShapeKind> {
        let tables = &mut self.world.tables;
        Some(match shape {
            Shape::Prism(prism) => {
                let profile = crate::scene::prism_profile(prism.spline, &prism.points).ok()?;
                tables.prisms.push(PrismData::new(
                    &profile.segments,
                    prism.height1,
                    prism.height2,
                    prism.conic,
                    prism.open,
                ));
                ShapeKind::Prism((tables.prisms.len() - 1) as u32)
            }
            Shape::Glyph(glyph) => {
                let data = PrismData::new(&glyph.segments, 0.0, glyph.depth, false, false);
                tables.prisms.push(data);
                ShapeKind::Prism((tables.prisms.len() - 1) as u32)
            }
            Shape::Sor(sor) => {
                let segments = crate::scene::sor_profile(&sor.points).ok()?;
                tables.sors.push(SorData::new(&segments, sor.open));
                ShapeKind::Sor((tables.sors.len() - 1) as u32)
            }
            Shape::Lathe(lathe) => {
                let segments = crate::scene::lathe_profile(lathe.spline, &lathe.points).ok()?;
                tables.lathes.push(LatheData::new(&segments));
                ShapeKind::Lathe((tables.lathes.len() - 1) as u32)
            }
            _ => return None,
        })
    }
}

/// The interior with the caustics an old scene wrote in the finish: POV-Ray 3.7 gives the
/// interior a 45th of them (see `Finish::caustics`), unless the interior has its own.
fn with_finish_caustics(mut interior: Interior, texture: &Texture) -> Interior {
    if interior.caustics == 0.0 && texture.finish.caustics != 0.0 {
        interior.caustics = texture.finish.caustics / 45.0;
    }
    interior
}

fn mask(f: ObjectFlags) -> u8 {
    let mut m = 0;
    if f.no_shadow {
        m |= flags::NO_SHADOW;
    }
    if f.no_image {
        m |= flags::NO_IMAGE;
    }
    if f.no_reflection {
        m |= flags::NO_REFLECTION;
    }
    if f.no_radiosity {
        m |= flags::NO_RADIOSITY;
    }
    if f.photons.is_some_and(|p| p.pass_through) {
        m |= flags::PHOTON_PASS;
    }
    if f.inverse {
        m |= flags::INVERSE;
    }
    m
}

/// The render form of a mesh: single-precision arrays, and per-face index lists only for
/// what some face has. `None` without faces.
fn mesh_data(mesh: &Mesh) -> Option<MeshData> {
    if mesh.faces.is_empty() {
        return None;
    }
    let f32s = |v: &DVec3| v.as_vec3().to_array();
    let mut data = MeshData::default();
    data.vertices = mesh.vertices.iter().map(f32s).collect();
    // Unit length as POV-Ray keeps them: interpolation weighs each corner alike.
    data.normals = mesh
        .normals
        .iter()
        .map(|n| f32s(&n.normalize_or(DVec3::Y)))
        .collect();
    data.uvs = mesh.uvs.iter().map(|v| v.as_vec2().to_array()).collect();
    data.faces = mesh.faces.iter().map(|f| f.vertices).collect();
    data.inside_vector = mesh.inside_vector;
    let list = |pick: fn(&MeshFace) -> Option<[u32; 3]>| {
        if mesh.faces.iter().any(|f| pick(f).is_some()) {
            let none = [NO_INDEX; 3];
            mesh.faces.iter().map(|f| pick(f).unwrap_or(none)).collect()
        } else {
            Vec::new()
        }
    };
    data.face_normals = list(|f| f.normals);
    data.face_uvs = list(|f| f.uvs);
    data.face_textures = list(|f| f.textures);
    Some(data)
}

/// A polygon's loops in 2D coordinates of its plane, and the frame back to 3D.
fn polygon(points: &[DVec3]) -> Option<(PolygonData, Transform)> {
    // Newell's normal is robust for any planar polygon, convex or not.
    let mut normal = DVec3::ZERO;
    for (i, a) in points.iter().enumerate() {
        let b = points[(i + 1) % points.len()];
        normal += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    let origin = *points.first()?;
    let frame = axis_frame(origin, origin + normal.try_normalize()?)?;
    let local: Vec<DVec2> = points
        .iter()
        .map(|&p| frame.inverse_point(p).truncate())
        .collect();
    let mut loops = Vec::new();
    let mut kept = Vec::new();
    let mut start = 0;
    let mut i = 0;
    while i < local.len() {
        kept.push(local[i]);
        let first = kept[start];
        if kept.len() - start > 1 && local[i] == first {
            kept.pop();
            if kept.len() - start >= 3 {
                loops.push((start, kept.len()));
            } else {
                kept.truncate(start);
            }
            start = kept.len();
        }
        i += 1;
    }
    if kept.len() - start >= 3 {
        loops.push((start, kept.len()));
    }
    if loops.is_empty() {
        return None;
    }
    let lo = kept
        .iter()
        .fold(DVec2::splat(f64::INFINITY), |a, p| a.min(*p));
    let hi = kept
        .iter()
        .fold(DVec2::splat(f64::NEG_INFINITY), |a, p| a.max(*p));
    Some((
        PolygonData {
            points: kept,
            loops,
            bounds: (lo, hi),
        },
        frame,
    ))
}

#[cfg(test)]
mod tests {
    use super::GammaDecode;

    /// The decode through logarithms is the power to about |g log2 c| roundings, over the
    /// values a traced sample takes (negative ones clamp to 0).
    #[test]
    fn a_power_decode_is_the_power() {
        for g in [0.45, 1.5, 1.8, 2.2, 2.5] {
            let mut c = 1e-8;
            while c < 1e4 {
                let (got, want) = (GammaDecode::Power(g).decode(c), c.powf(g));
                let bound = (g * c.log2()).abs().max(1.0) * 4.0 * f64::EPSILON;
                assert!((got / want - 1.0).abs() <= bound, "{g} {c}: {got} {want}");
                c *= 1.37;
            }
            assert_eq!(GammaDecode::Power(g).decode(0.0), 0.0);
            assert_eq!(GammaDecode::Power(g).decode(-0.3), 0.0);
        }
    }
}
