//! What a texture shows at one point, in the form the integrator shades: a short list of
//! layers (pigment colour, finish, normal perturbation), top layer first. Patterned and
//! layered textures resolve here, so the integrator never looks inside a texture.

use glam::DVec3;

use crate::geometry::TexturePoint;
use crate::scene::{Colour, Finish, PatternKind, Pigment, PigmentKind, Texture, TextureMap};

use super::blend::{Blend, blend_position, mix};
use super::evaluate_pigment;
use super::noise::lattice_hash;
use super::normal::perturb;
use super::pattern::pattern_value_at;

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

/// Resolves a texture at a world-space point: the texture itself, then the layers below
/// it. A patterned texture (texture_map) contributes its entry at the point; between two
/// entries the colours blend and the finish of the nearer entry is used (exact when the
/// entries share a finish, which is how texture maps are mostly written).
pub fn texture_layers<'a>(texture: &'a Texture, at: impl Into<TexturePoint>) -> Layers<'a> {
    let p = at.into();
    let mut layers = Layers::default();
    push_texture(&mut layers, texture, p, 0);
    for below in &texture.below {
        push_texture(&mut layers, below, p, 0);
    }
    layers
}

/// A surface that mixes textures (a mesh face with a texture per corner, a blob with
/// textured components): each texture's top layer at the point, their colours mixed by
/// `weights` as POV-Ray mixes them, with the finish of the heaviest (exact when they share
/// a finish, as for texture maps here).
pub fn blended_layers<'a>(
    textures: impl Iterator<Item = (&'a Texture, f64)>,
    at: impl Into<TexturePoint>,
) -> Layers<'a> {
    let p = at.into();
    let mut colour = Colour::default();
    let mut total = 0.0;
    let mut finish: Option<(&Finish, f64)> = None;
    for (t, w) in textures {
        let layers = texture_layers(t, p);
        let Some(top) = layers.iter().next() else {
            continue;
        };
        colour.rgb += top.colour.rgb * w;
        colour.filter += top.colour.filter * w;
        colour.transmit += top.colour.transmit * w;
        total += w;
        if finish.is_none_or(|(_, best)| w > best) {
            finish = Some((top.finish, w));
        }
    }
    let mut out = Layers::default();
    if let Some((finish, _)) = finish
        && total > 0.0
    {
        colour.rgb /= total;
        colour.filter /= total;
        colour.transmit /= total;
        out.push(Layer { colour, finish });
    }
    out
}

/// Texture maps nest; beyond this depth a texture shows its own pigment.
const MAX_NESTING: u32 = 8;

fn push_texture<'a>(layers: &mut Layers<'a>, t: &'a Texture, p: TexturePoint, depth: u32) {
    if let Some(map) = &t.map
        && depth < MAX_NESTING
    {
        if matches!(map.pattern.kind, PatternKind::Average) {
            if let Some(i) = average_pick(map, p.world) {
                push_texture(layers, &map.entries[i].1, p, depth + 1);
            }
            return;
        }
        let q = map.transform.inverse_point(map_point(map, p));
        let v = pattern_value_at(&map.pattern, q, p.normal);
        match blend_position(&map.entries, v, |e| e.0) {
            Blend::One(i) => push_texture(layers, &map.entries[i].1, p, depth + 1),
            Blend::Two(i, w) => {
                let (a, b) = (&map.entries[i].1, &map.entries[i + 1].1);
                let mut top_a = Layers::default();
                push_texture(&mut top_a, a, p, depth + 1);
                let mut top_b = Layers::default();
                push_texture(&mut top_b, b, p, depth + 1);
                let (Some(la), Some(lb)) = (top_a.iter().next(), top_b.iter().next()) else {
                    return;
                };
                layers.push(Layer {
                    colour: mix(&la.colour, &lb.colour, w),
                    finish: if w < 0.5 { la.finish } else { lb.finish },
                });
            }
            Blend::None => {}
        }
        return;
    }
    layers.push(Layer {
        colour: evaluate_pigment(&t.pigment, p),
        finish: &t.finish,
    });
}

/// The shading normal after the texture's normal perturbation: `n` is the unit normal
/// facing the viewer. The top layer's normal (or that of the texture-map entry at the
/// point) applies.
pub fn perturbed_normal(texture: &Texture, at: impl Into<TexturePoint>, n: DVec3) -> DVec3 {
    let p = at.into();
    let mut t = texture;
    for _ in 0..MAX_NESTING {
        let Some(map) = &t.map else { break };
        let q = map.transform.inverse_point(map_point(map, p));
        let v = pattern_value_at(&map.pattern, q, n);
        if matches!(map.pattern.kind, PatternKind::Average) {
            match average_pick(map, p.world) {
                Some(i) => t = &map.entries[i].1,
                None => return n,
            }
            continue;
        }
        t = match blend_position(&map.entries, v, |e| e.0) {
            Blend::One(i) => &map.entries[i].1,
            Blend::Two(i, w) => &map.entries[if w < 0.5 { i } else { i + 1 }].1,
            Blend::None => return n,
        };
    }
    match &t.normal {
        Some(normal) => perturb(normal, p.world, n),
        None => n,
    }
}

/// `average texture_map`: POV-Ray shades every entry fully (its own finish and normal) and
/// averages the results by weight. penumbra picks one entry per hit point instead, with
/// probability weight / total from a hash of the point, so that each sample shades one
/// whole texture and the pixel's expectation is POV-Ray's average. Texture and normal
/// read the same pick, as both hash the same point.
fn average_pick(map: &TextureMap, world: DVec3) -> Option<usize> {
    let total: f64 = map.entries.iter().map(|e| e.0.max(0.0)).sum();
    if total <= 0.0 || total.is_nan() {
        return None;
    }
    let bits = world.to_array().map(|c| c.to_bits());
    let mix = |b: u64| (b ^ (b >> 32)) as i64;
    let h = lattice_hash(mix(bits[0]), mix(bits[1]), mix(bits[2]), AVERAGE_SEED);
    let mut u = f64::from(h) / (f64::from(u32::MAX) + 1.0) * total;
    for (i, (w, _)) in map.entries.iter().enumerate() {
        u -= w.max(0.0);
        if u < 0.0 {
            return Some(i);
        }
    }
    map.entries.iter().rposition(|e| e.0 > 0.0)
}

const AVERAGE_SEED: u32 = 0x1f83_d9ab;

/// Where a texture map's pattern is evaluated: the world point, or (u, v, 0).
fn map_point(map: &TextureMap, p: TexturePoint) -> DVec3 {
    if map.uv_mapping {
        p.uv.extend(0.0)
    } else {
        p.world
    }
}

/// Whether a texture can let light through anywhere (filter or transmit > 0 in any pigment
/// entry). Opaque textures let shadow rays stop at the first hit.
pub fn may_transmit(texture: &Texture) -> bool {
    fn pigment(p: &Pigment) -> bool {
        match &p.kind {
            PigmentKind::Solid(c) => c.filter > 0.0 || c.transmit > 0.0,
            PigmentKind::List { entries, .. } => entries.iter().any(pigment),
            PigmentKind::ColourMap { map, .. } => {
                map.iter().any(|(_, c)| c.filter > 0.0 || c.transmit > 0.0)
            }
            PigmentKind::PigmentMap { map, .. } => map.iter().any(|(_, p)| pigment(p)),
            PigmentKind::Image(im) => {
                im.once
                    || im.filter_all > 0.0
                    || im.transmit_all > 0.0
                    || im
                        .image
                        .pixels
                        .iter()
                        .any(|c| c.filter > 0.0 || c.transmit > 0.0)
            }
        }
    }
    let own = match &texture.map {
        Some(m) => m.entries.iter().any(|(_, t)| may_transmit(t)),
        None => pigment(&texture.pigment),
    };
    own || texture.below.iter().any(may_transmit)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Pattern, PatternKind, Transform};

    #[test]
    fn texture_map_picks_and_blends_entries() {
        let red = Texture {
            pigment: Pigment::solid(Colour::rgb(1.0, 0.0, 0.0)),
            ..Texture::default()
        };
        let blue = Texture {
            pigment: Pigment::solid(Colour::rgb(0.0, 0.0, 1.0)),
            ..Texture::default()
        };
        let t = Texture {
            map: Some(Box::new(TextureMap {
                pattern: Pattern::new(PatternKind::Gradient(DVec3::X)),
                transform: Transform::IDENTITY,
                entries: vec![(0.0, red), (1.0, blue)],
                uv_mapping: false,
            })),
            ..Texture::default()
        };
        let l = texture_layers(&t, DVec3::new(0.25, 0.0, 0.0));
        assert_eq!(l.len(), 1);
        let c = l.iter().next().unwrap().colour.rgb;
        assert!((c - DVec3::new(0.75, 0.0, 0.25)).length() < 1e-9);
        assert!(!may_transmit(&t));
    }

    #[test]
    fn layers_come_top_first() {
        let mut clear = Colour::rgb(1.0, 1.0, 1.0);
        clear.transmit = 0.5;
        let bottom = Texture {
            pigment: Pigment::solid(Colour::rgb(0.0, 1.0, 0.0)),
            ..Texture::default()
        };
        let top = Texture {
            pigment: Pigment::solid(clear),
            below: vec![bottom],
            ..Texture::default()
        };
        let l = texture_layers(&top, DVec3::ZERO);
        let v: Vec<_> = l.iter().map(|x| x.colour).collect();
        assert_eq!(v.len(), 2);
        assert_eq!(v[0], clear);
        assert_eq!(v[1].rgb, DVec3::new(0.0, 1.0, 0.0));
        assert!(may_transmit(&top));
    }
}
