//! The render-ready scene: the scene model flattened into primitives with world-space
//! transforms and a BVH, each pointing at its material, plus lights prepared for sampling.

use crate::geometry::{Transform, World, WorldBuilder, flags};
use crate::scene::{Camera, Colour, GlobalSettings, Object, ObjectFlags, Scene, Shape, Texture};

use super::lights::PreparedLight;
use crate::geometry::ShapeKind;

#[derive(Clone, Debug)]
pub struct Material {
    pub texture: Texture,
    pub double_illuminate: bool,
}

#[derive(Clone, Debug)]
pub struct PreparedScene {
    pub world: World,
    pub materials: Vec<Material>,
    pub lights: Vec<PreparedLight>,
    pub camera: Camera,
    pub background: Colour,
    pub settings: GlobalSettings,
    pub legacy: bool,
}

impl PreparedScene {
    pub fn new(scene: &Scene) -> PreparedScene {
        let mut builder = WorldBuilder::default();
        let mut materials = Vec::new();
        let default_texture = Texture::default();
        for object in &scene.objects {
            flatten(
                object,
                &default_texture,
                ObjectFlags::default(),
                &mut builder,
                &mut materials,
            );
        }
        PreparedScene {
            world: builder.build(),
            materials,
            lights: scene.lights.iter().map(PreparedLight::new).collect(),
            camera: scene.camera.clone(),
            background: scene.background,
            settings: scene.settings.clone(),
            legacy: scene.legacy(),
        }
    }
}

/// Unions are groups for rendering: their children become primitives of their own, taking
/// the union's texture where they have none and its flags in addition to theirs.
fn flatten(
    object: &Object,
    inherited: &Texture,
    inherited_flags: ObjectFlags,
    builder: &mut WorldBuilder,
    materials: &mut Vec<Material>,
) {
    let texture = object.texture.as_ref().unwrap_or(inherited);
    let f = object.flags;
    let combined = ObjectFlags {
        no_shadow: f.no_shadow || inherited_flags.no_shadow,
        no_image: f.no_image || inherited_flags.no_image,
        no_reflection: f.no_reflection || inherited_flags.no_reflection,
        hollow: f.hollow || inherited_flags.hollow,
        inverse: f.inverse,
        double_illuminate: f.double_illuminate || inherited_flags.double_illuminate,
    };
    let kind = match &object.shape {
        Shape::Union(children) => {
            for child in children {
                flatten(child, texture, combined, builder, materials);
            }
            return;
        }
        Shape::Sphere { center, radius } => ShapeKind::Sphere {
            center: *center,
            radius: *radius,
        },
        Shape::Plane { normal, distance } => ShapeKind::Plane {
            normal: *normal,
            distance: *distance,
        },
        Shape::Box { corner1, corner2 } => ShapeKind::Box {
            min: corner1.min(*corner2),
            max: corner1.max(*corner2),
        },
    };
    let mut mask = 0;
    if combined.no_shadow {
        mask |= flags::NO_SHADOW;
    }
    if combined.no_image {
        mask |= flags::NO_IMAGE;
    }
    if combined.no_reflection {
        mask |= flags::NO_REFLECTION;
    }
    materials.push(Material {
        texture: texture.clone(),
        double_illuminate: combined.double_illuminate,
    });
    let transform: &Transform = &object.transform;
    builder.add(kind, transform, (materials.len() - 1) as u32, mask);
}
