//! What a texture shows at one point, in the form the integrator shades: a short list of
//! layers (pigment colour, finish, normal perturbation), top layer first. Patterned and
//! layered textures resolve here, so the integrator never looks inside a texture.

use glam::DVec3;

use crate::scene::{Colour, Finish, Texture};

use super::evaluate_pigment;

/// At most this many layers are shaded; POV-Ray scenes rarely stack more than a few.
pub const MAX_LAYERS: usize = 8;

#[derive(Clone, Copy, Debug)]
pub struct Layer<'a> {
    pub colour: Colour,
    pub finish: &'a Finish,
}

/// A fixed-capacity list, so resolving a texture allocates nothing per ray.
#[derive(Clone, Copy, Debug)]
pub struct Layers<'a> {
    layers: [Option<Layer<'a>>; MAX_LAYERS],
    len: usize,
}

impl<'a> Default for Layers<'a> {
    fn default() -> Self {
        Layers {
            layers: [None; MAX_LAYERS],
            len: 0,
        }
    }
}

impl<'a> Layers<'a> {
    pub fn push(&mut self, layer: Layer<'a>) {
        if self.len < MAX_LAYERS {
            self.layers[self.len] = Some(layer);
            self.len += 1;
        }
    }

    pub fn iter(&self) -> impl Iterator<Item = &Layer<'a>> {
        self.layers[..self.len].iter().flatten()
    }

    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

/// Resolves a texture at a world-space point.
pub fn texture_layers<'a>(texture: &'a Texture, p: DVec3) -> Layers<'a> {
    let mut layers = Layers::default();
    layers.push(Layer {
        colour: evaluate_pigment(&texture.pigment, p),
        finish: &texture.finish,
    });
    layers
}

/// The shading normal after the texture's normal perturbation (none yet): `n` is the unit
/// normal facing the viewer.
pub fn perturbed_normal(_texture: &Texture, _p: DVec3, n: DVec3) -> DVec3 {
    n
}

/// Whether a texture can let light through anywhere (filter or transmit > 0 in any pigment
/// entry). Opaque textures let shadow rays stop at the first hit.
pub fn may_transmit(texture: &Texture) -> bool {
    fn pigment(p: &crate::scene::Pigment) -> bool {
        match &p.kind {
            crate::scene::PigmentKind::Solid(c) => c.filter > 0.0 || c.transmit > 0.0,
            crate::scene::PigmentKind::List { entries, .. } => entries.iter().any(pigment),
        }
    }
    pigment(&texture.pigment)
}
