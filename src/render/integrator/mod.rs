//! The integrator answers one question: what radiance comes back along a ray. It is
//! POV-Ray's recursive Whitted tracer (ambient, diffuse, highlights, shadow rays through
//! filtering objects, mirror reflection, refraction) with stochastic changes that keep
//! POV-Ray's expectation: area-light visibility is estimated from one grid point drawn with
//! POV-Ray's weights, the deterministic adc_bailout cut is replaced by Russian roulette
//! (expectation: the max_trace_level-capped tree; not in gamma-space scenes, see
//! `Termination`), and where a surface both reflects and
//! refracts, one branch may be chosen at random in proportion to its weight.

//!
//! A reader's map: [`Integrator::trace`] finds the hit and builds one [`Shading`] record,
//! `shade` composites the texture's layers (each lit by `direct.rs`), then follows the
//! reflected and transmitted branches (`secondary`). Every random decision reads the
//! sampler dimension [`DimensionLayout`] assigns to it. `optics.rs` holds Fresnel,
//! refraction and fade; `interiors.rs` the stack of interiors a ray is inside.

mod direct;
mod dispersion;
mod interiors;
mod media;
mod optics;
mod photons;
mod radiosity;

pub use optics::{fresnel, refract};

use glam::DVec3;

use crate::appearance::finish::{metallic_tint, reflectivity};
use crate::appearance::texture::Layers;
use crate::appearance::{blended_layers, perturbed_normal, sky_colour, texture_layers};
use crate::geometry::{Hit, Ray, SurfacePoint, TexturePoint, flags, offset_point};
use crate::scene::{Colour, Finish, Radiosity};

use super::RenderOptions;
use super::dimensions::{DimensionLayout, Purpose};
use super::lights::{AreaLightMode, LightSamples};
use super::photons::PhotonMaps;
use super::prepared::{Material, PreparedScene};
use super::sampler::PixelSampler;
use crate::render::fog::{Segment, fog_effect};
use crate::render::rainbow;
use direct::ShadedLayer;
use interiors::InteriorStack;
use optics::{fade, mirror_direction};

/// Below this path weight, Russian roulette starts, within the first [`SHALLOW_LEVELS`]
/// of a ray tree. A branch that survives it is divided by its survival probability, as
/// much as 20 times brighter, and at 0.1 those were most of the noise where mirrors see
/// each other: 640x480 adaptive, 2 seeds, RMSE against POV-Ray's k = 8 reference at 2 / 4 /
/// 8 / 16 spp, reflection.pov 0.00329 / 0.00187 / 0.00111 / 0.00066 -> 0.00127 / 0.00077 /
/// 0.00047 / 0.00035 for 1-5% more time, glass.pov 0.0122 / 0.0074 / 0.0048 / 0.0036 ->
/// 0.0081 / 0.0053 / 0.0038 / 0.0031 for 2-10% more (0.003 took glass 6-10% more time
/// again for 1-2% less error).
const ROULETTE_WEIGHT: f64 = 0.01;
/// Roulette's threshold past the first [`SHALLOW_LEVELS`]: there a tree that both reflects
/// and refracts doubles at every level, and tracing it down to 0.01 took glass stacked 50
/// levels deep (advanced/blocks/stackertransp.pov, 160x120, 4 spp) from 1.0 M rays to 2.9
/// M, 3 times the time for 11% less noise.
const DEEP_ROULETTE_WEIGHT: f64 = 0.1;
/// The levels of POV-Ray's default max_trace_level, where most scenes' trees end.
const SHALLOW_LEVELS: u32 = 5;
/// The smallest survival probability, which bounds the variance roulette can add.
const ROULETTE_MIN_Q: f64 = 0.05;

/// Rays traced, by kind, for the statistics line.
#[derive(Clone, Copy, Debug, Default)]
pub struct RayCounts {
    pub camera: u64,
    pub shadow: u64,
    pub secondary: u64,
    /// Shadow rays towards area lights that arrived (wholly or in part) and that were
    /// stopped (wholly or in part): where pixels close together have both, they see a
    /// penumbra (adaptive sampling's pilot reads them per pixel).
    pub area_lit: u64,
    pub area_shadowed: u64,
    /// Shadow rays towards area lights left untraced because nothing meets their shaft
    /// ([`crate::geometry::Shaft`]): a pixel's cost to adaptive sampling still counts
    /// them ([`RayCounts::work`]).
    pub spared: u64,
}

impl RayCounts {
    pub fn add(&mut self, o: &RayCounts) {
        self.camera += o.camera;
        self.shadow += o.shadow;
        self.secondary += o.secondary;
        self.area_lit += o.area_lit;
        self.area_shadowed += o.area_shadowed;
        self.spared += o.spared;
    }

    pub fn total(&self) -> u64 {
        self.camera + self.shadow + self.secondary
    }

    /// A pixel's cost to adaptive sampling: its rays, and the shadow rays its shafts
    /// spared, so that the shafts change no decision. Measured at 640x480 against POV-Ray
    /// (2 seeds, RMSE at 2 / 4 / 8 spp) with the spared rays left out of the cost: the lit
    /// pixels, cheaper, took more of the samples and did less with them than the
    /// penumbrae would have: area_adaptive 0.00179 / 0.00117 / 0.00084 against 0.00147 /
    /// 0.00100 / 0.00073 counted, and at 2 spp 4.75 G instructions against 5.94 G
    /// (callgrind), so 16% more squared error times instructions; soft_shadow and
    /// area_circular_9x9 at 8 spp 0.00107 and 0.00085 against 0.00087 and 0.00068.
    pub fn work(&self) -> u64 {
        self.total() + self.spared
    }
}

/// What to do where a ray tree splits into a reflected and a refracted branch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Splitting {
    /// Trace both branches, as POV-Ray does.
    #[default]
    Both,
    /// Trace one, chosen with probability proportional to its weight, divided by that
    /// probability: the same expectation at about half the rays per level.
    One,
}

/// The state a ray carries down the tree.
#[derive(Clone, Copy, Debug)]
struct Path {
    /// Surfaces along the path so far, 1 for the camera ray: POV-Ray returns black for a
    /// ray whose level exceeds max_trace_level.
    level: u32,
    /// Product of the branch weights (max components), for roulette.
    weight: f64,
    skip: u8,
    interiors: InteriorStack,
    /// The wavelength parameter the ray took at a dispersing refraction (`dispersion.rs`).
    wavelength: Option<f64>,
    /// Radiosity rays (diffuse bounces) on the path so far: they count no trace level, as
    /// in POV-Ray, but the decisions after each read a block of dimensions of their own.
    bounces: u32,
}

/// Dimension blocks per diffuse bounce: more than the deepest trace level (256), so that
/// (level, bounces) pairs never share a block.
const BLOCKS_PER_BOUNCE: u32 = 257;

impl Path {
    /// The block of sampler dimensions the decisions at this path's next hit read: the
    /// trace level's, moved along by the diffuse bounces taken (a path without radiosity
    /// reads exactly the trace level's block).
    fn block(&self) -> u32 {
        self.level + self.bounces * BLOCKS_PER_BOUNCE
    }
}

/// Everything shading needs to know about one hit, built once per hit in `trace`.
struct Shading<'s> {
    /// The hit point with its outward geometric normal (`surface.normal`). Borrowed from
    /// the caller's frame: held by value, its 136 bytes were copied into every shading
    /// (a call to memcpy, 4% of scenes/checker.pov's time in perf).
    surface: &'s SurfacePoint,
    /// The incoming ray's unit direction.
    d: DVec3,
    /// The shading normal, perturbed by the texture's `normal`, turned to face the ray.
    n: DVec3,
    /// The same before the texture's `normal`: radiosity gathers around it by default.
    facing: DVec3,
    material: &'s Material,
    /// Whether the ray leaves the material's interior here (see [`InteriorStack`]).
    leaving: bool,
    /// A ray that crossed this object's interior to get here fades, but only in what the
    /// surface lets through from beyond: POV-Ray leaves the surface's own shading (its
    /// highlights seen from inside) and its internal reflection unfaded (measured: a
    /// transparent sphere's inner highlight keeps its full strength at fade_power 0, whose
    /// fade halves what is seen through the sphere; shadow rays do not fade at power 0).
    fade_through: DVec3,
    /// Where shadow rays start: just off the surface, on the ray's side.
    shadow_origin: DVec3,
    /// The path so far, borrowed: a copy would move its interior stack with every shading.
    path: &'s Path,
}

impl Shading<'_> {
    /// Where the texture is looked up: the hit with its perturbed, viewer-facing normal
    /// (POV-Ray's slope pattern reads the bumped normal: a `normal { bumps }` beside it
    /// changes its values by up to 0.8).
    fn texture_point(&self) -> TexturePoint {
        TexturePoint {
            normal: self.n,
            ..TexturePoint::from(self.surface)
        }
    }
}

/// What the texture's layers leave for the secondary rays: the top layer's pigment and
/// finish, which decide reflection, and what all the layers together let through.
struct Top<'f> {
    pigment: Colour,
    finish: &'f Finish,
    through: DVec3,
}

/// Where a surface sends the rest of the light, and how much of it, per channel.
#[derive(Clone, Copy)]
struct Branches {
    mirror: DVec3,
    reflect: DVec3,
    /// The transmitted direction; `None` under total internal reflection.
    refracted: Option<DVec3>,
    /// The same index of refraction on both sides: the ray goes on straight and counts no
    /// trace level.
    straight: bool,
    transmit: DVec3,
    /// The interiors beyond the surface.
    beyond: InteriorStack,
}

/// A ray the tree continues with, and the roulette that may end it.
struct Branch {
    dir: DVec3,
    level: u32,
    skip: u8,
    interiors: InteriorStack,
    wavelength: Option<f64>,
    /// The path's weight along this branch, before roulette.
    weight: f64,
    /// Whether the branch's light enters linearly (a reflection exponent does not), which
    /// roulette needs to stay unbiased.
    linear: bool,
    roulette: Purpose,
}

/// Which branches to follow, each with the probability it was chosen with.
struct Choice {
    reflect: Option<f64>,
    transmit: Option<f64>,
}

/// How a ray tree ends below max_trace_level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Termination {
    /// Russian roulette on low-weight branches: unbiased for the capped tree.
    Roulette,
    /// POV-Ray's own cut: a branch whose weight falls below adc_bailout is not traced. A
    /// scene computed in gamma space decodes each sample (x^g), where roulette's noise
    /// would become brightness (E[x^g] > E[x]^g; measured: a plane of transmit 0.01 before
    /// an emitter of 1, assumed_gamma 2.2, read 0.00064 with roulette, 20 times POV-Ray's
    /// 0.0000398), so there the tree ends as POV-Ray's does.
    AdcBailout,
    /// Every branch to max_trace_level (`--no-roulette` in a linear scene).
    Full,
}

pub struct Integrator<'a> {
    scene: &'a PreparedScene,
    layout: DimensionLayout,
    termination: Termination,
    splitting: Splitting,
    area_lights: AreaLightMode,
    /// Shadow rays per area light per shading point (more where soft shadows dominate the
    /// noise; each camera sample then costs more).
    light_samples: LightSamples,
    /// POV-Ray's `+Q` level (see [`RenderOptions::quality`]).
    quality: u32,
    /// The interiors the camera is in: camera rays start there (no fog inside a solid
    /// object, and the index of refraction of a transparent one).
    camera_interiors: InteriorStack,
    /// The scene's radiosity, where this quality computes it.
    radiosity: Option<Radiosity>,
    /// What finishes' `ambient` is lit by: the scene's ambient_light, or nothing where
    /// radiosity replaces it (scenes of `#version` 3.7 on; measured: ambient 0.3 changes
    /// nothing with radiosity on, and adds ambient * ambient_light to each bounce in 3.6).
    ambient_light: DVec3,
    /// The photon passes the samples being rendered gather from (`None`: no caustics).
    photons: Option<&'a PhotonMaps>,
    /// For adaptive sampling's one-ray pixels, around which every shadow ray of the pilot
    /// agreed: one shadow ray per area light is exact there, so it stands in for POV-Ray's
    /// `adaptive` rule too, whose corner rays would agree as well ([`Self::one_ray`]).
    one_ray: bool,
    /// Whether every sample shades a small area_illumination grid whole
    /// ([`direct::WHOLE_GRID_FROM_SPP`]).
    whole_grid: bool,
}

/// `+Q` levels: from these on, POV-Ray shows diffuse light, shadows, area lights, and
/// reflected and refracted rays.
pub(super) const QUALITY_LIGHTING: u32 = 2;
pub(super) const QUALITY_SHADOWS: u32 = 4;
pub(super) const QUALITY_AREA_LIGHTS: u32 = 5;
pub(super) const QUALITY_RAYS: u32 = 8;
/// From +Q9 on, POV-Ray computes media (measured: an emitting slab shows at 9, not 8).
pub(super) const QUALITY_MEDIA: u32 = 9;
/// Radiosity too starts at +Q9 (measured: a diffuse furnace gathers nothing at +Q8).
pub(super) const QUALITY_RADIOSITY: u32 = 9;

impl<'a> Integrator<'a> {
    pub fn new(scene: &'a PreparedScene, options: &RenderOptions) -> Integrator<'a> {
        let radiosity = scene
            .settings
            .radiosity
            .filter(|_| options.quality >= QUALITY_RADIOSITY);
        let ambient_light = if radiosity.is_some() && !scene.legacy {
            DVec3::ZERO
        } else {
            scene.settings.ambient_light
        };
        Integrator {
            radiosity,
            ambient_light,
            scene,
            layout: scene.dimension_layout(),
            termination: if scene.output_gamma.is_some() {
                Termination::AdcBailout
            } else if options.roulette {
                Termination::Roulette
            } else {
                Termination::Full
            },
            splitting: options.splitting,
            area_lights: options.area_lights,
            light_samples: options.light_samples,
            quality: options.quality,
            camera_interiors: camera_interiors(scene),
            photons: None,
            one_ray: false,
            whole_grid: options
                .average_spp
                .unwrap_or(f64::from(options.samples_per_pixel))
                >= direct::WHOLE_GRID_FROM_SPP,
        }
    }

    /// The same integrator for pixels around which every shadow ray towards an area light
    /// agreed (adaptive sampling's one-ray pixels): one shadow ray per area light, even
    /// where POV-Ray's `adaptive` rule would test the grid's corners and find them all
    /// agreeing (scenes/area_adaptive.pov at 640x480, 4 spp: 19.3 M rays -> 15.4 M, one
    /// thread 1.40 -> 1.19 s; 10 of its 307,200 pixels changed, by at most 0.0023).
    pub fn one_ray(self) -> Integrator<'a> {
        Integrator {
            one_ray: true,
            ..self
        }
    }

    /// The same integrator, gathering caustics from these photon passes.
    pub fn with_photons(self, photons: &'a PhotonMaps) -> Integrator<'a> {
        Integrator {
            photons: Some(photons),
            ..self
        }
    }

    /// Which sampler dimension each decision reads; the camera's come first.
    pub fn layout(&self) -> &DimensionLayout {
        &self.layout
    }

    /// Radiance along a camera ray.
    pub fn radiance(&self, ray: &Ray, sampler: &mut PixelSampler, counts: &mut RayCounts) -> DVec3 {
        counts.camera += 1;
        let path = Path {
            level: 1,
            weight: 1.0,
            skip: flags::NO_IMAGE,
            interiors: self.camera_interiors,
            wavelength: None,
            bounces: 0,
        };
        let l = self.trace(ray, path, sampler, counts);
        match self.scene.output_gamma {
            // Per sample, as POV-Ray decodes each traced ray; where the estimate is noisy
            // (area lights) the curve's bend adds a small bias (docs/differences.md).
            Some(g) => l.map(|c| g.decode(c)),
            None => l,
        }
    }

    fn trace(
        &self,
        ray: &Ray,
        path: Path,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        // A mesh camera's `max_distance` ends the camera rays (src/render/mesh_camera.rs).
        let reach = if path.level == 1 && path.bounces == 0 {
            self.scene.camera_reach
        } else {
            f64::INFINITY
        };
        let hit = self.scene.world.intersect(ray, reach, path.skip);
        let seen = match &hit {
            Some(hit) => {
                let surface = self.scene.world.surface(ray, hit);
                self.shade(&self.shading(ray, hit, &surface, &path), sampler, counts)
            }
            None => self.sky(ray.direction),
        };
        let media = !self.scene.media.is_empty()
            && self.quality >= QUALITY_MEDIA
            && (path.bounces == 0 || self.radiosity.is_some_and(|r| r.media));
        let atmosphere = !self.scene.fogs.is_empty() || !self.scene.rainbows.is_empty();
        if (!atmosphere && !media) || !path.interiors.in_atmosphere() {
            return seen;
        }
        let scale = ray.direction.length();
        let segment = Segment {
            origin: ray.origin,
            direction: ray.direction / scale,
            length: hit.map_or(f64::INFINITY, |h| h.t * scale),
        };
        let seen = if media {
            self.media_effect(&segment, &path.interiors, path.block(), sampler, counts)
                .apply(seen)
        } else {
            seen
        };
        // Rainbows before fogs: not measured together (no example scene has both).
        let seen = if self.scene.rainbows.is_empty() {
            seen
        } else {
            let u = rainbow::jitter_number(segment.direction);
            rainbow::rainbow_effect(&self.scene.rainbows, &segment, u).apply(seen)
        };
        fog_effect(&self.scene.fogs, &segment).apply(seen)
    }

    fn shading<'p>(
        &self,
        ray: &Ray,
        hit: &Hit,
        surface: &'p SurfacePoint,
        path: &'p Path,
    ) -> Shading<'p>
    where
        'a: 'p,
    {
        let d = ray.direction.normalize();
        // The ray meets the surface from behind, and whether it leaves the interior. As in
        // POV-Ray, a ray leaves an interior only if it is in it, whichever side it meets:
        // a ray crossing a disc or polygon from behind enters it (measured in a box of
        // absorbing media: behind a non-hollow disc facing either way the media stop, behind
        // a hollow one they go on; leaving on the side seen lost the box's media instead).
        let back = surface.normal.dot(d) > 0.0;
        let material = self.scene.side_material(surface.material, back);
        let leaving = path.interiors.contains(material.interior_id);
        let fade_through = if leaving && material.interior.fade_distance > 0.0 {
            fade(material, hit.t * ray.direction.length())
        } else {
            DVec3::ONE
        };
        // Turned by its own side, not the geometric normal's: POV-Ray flips an interpolated
        // normal that faces away from the ray, so where it grazes the view a smooth mesh
        // shows a crease (measured on a saddle seen edge-on and a twisted bicubic patch).
        let facing = if surface.shading_normal.dot(d) > 0.0 {
            -surface.shading_normal
        } else {
            surface.shading_normal
        };
        Shading {
            n: perturbed_normal(&material.texture, surface, facing),
            facing,
            shadow_origin: offset_point(surface.point, surface.normal, -d),
            surface,
            d,
            material,
            leaving,
            fade_through,
            path,
        }
    }

    /// The surface's own colour, layer by layer, then what it reflects and transmits.
    fn shade(&self, s: &Shading, sampler: &mut PixelSampler, counts: &mut RayCounts) -> DVec3 {
        let mut layers = self.layers(s);
        // The photons' light, gathered once per brilliance among the layers that show it
        // (a diffuse of zero, as glass has, shows none).
        let mut caustic: Option<(f64, DVec3)> = None;
        let mut colour = DVec3::ZERO;
        // Layers composite top first: each lets through what its own opacity does not cover.
        let mut through = DVec3::ONE;
        let mut top: Option<(Colour, &Finish)> = None;
        // What the layers together reflect diffusely, for radiosity.
        let mut diffuse = radiosity::Albedo::default();
        if self.quality < QUALITY_LIGHTING {
            // POV-Ray's quick colours: the pigment, fully lit.
            return layers.next().map_or(DVec3::ZERO, |l| l.colour.rgb);
        }
        // Each light's shadow, found for the first layer that needs it, serves the others.
        let mut memo = direct::ShadowMemo::default();
        for layer in layers {
            let c = layer.colour;
            let shaded = ShadedLayer {
                pigment: c,
                finish: layer.finish,
                att: c.opacity(self.scene.legacy),
            };
            colour += through * self.surface_light(s, &shaded, &mut memo, sampler, counts);
            if self.photons.is_some() && shaded.finish.diffuse * shaded.att != 0.0 {
                let b = layer.finish.brilliance;
                let e = match caustic {
                    Some((cb, e)) if cb == b => e,
                    _ => self.caustic(s, sampler.index(), b, false),
                };
                caustic = Some((b, e));
                colour += through * shaded.caustic(e, false);
            }
            if self.photons.is_some() && shaded.finish.diffuse_back * shaded.att != 0.0 {
                let e = self.caustic(s, sampler.index(), layer.finish.brilliance, true);
                colour += through * shaded.caustic(e, true);
            }
            diffuse.front += through * shaded.radiosity_albedo();
            diffuse.back += through * shaded.radiosity_albedo_back();
            top.get_or_insert((c, layer.finish));
            through *= c.rgb * c.filter + DVec3::splat(c.transmit);
            if through == DVec3::ZERO {
                break;
            }
        }
        if let Some(radiosity) = &self.radiosity
            && s.path.bounces < radiosity.recursion_limit
            && diffuse != radiosity::Albedo::default()
        {
            colour += self.gathered(s, radiosity, diffuse, sampler, counts);
        }
        let Some((pigment, finish)) = top else {
            return colour;
        };
        if s.path.level >= self.scene.settings.max_trace_level || self.quality < QUALITY_RAYS {
            return colour;
        }
        let top = Top {
            pigment,
            finish,
            through,
        };
        self.secondary(s, &top, colour, sampler, counts)
    }

    /// The texture's layers at the hit (a blend's mixed top layer where it has one).
    fn layers<'s>(&'s self, s: &Shading<'s>) -> Layers<'s> {
        match &s.surface.blend {
            Some(b) => blended_layers(
                self.scene
                    .world
                    .blend_weights(b)
                    .map(|(m, w)| (&*self.scene.materials[m as usize].texture, w)),
                s.texture_point(),
            ),
            None => texture_layers(&s.material.texture, s.texture_point()),
        }
    }

    /// Adds the reflected and transmitted light to the surface's own `colour`.
    fn secondary(
        &self,
        s: &Shading,
        top: &Top,
        mut colour: DVec3,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        // An opaque surface without reflection has no branch: the commonest surface skips
        // the refraction and Fresnel terms that would show it (7% of checker's instructions).
        if top.through == DVec3::ZERO && top.finish.reflection.is_zero() {
            return colour;
        }
        let b = branches(s, top);
        // By magnitude: POV-Ray takes `transmit -1` literally, subtracting what lies behind
        // (textures/pigments/transmitfx.pov).
        let reflect_weight = b.reflect.abs().max_element();
        let transmit_weight = b.transmit.abs().max_element();
        if reflect_weight <= 0.0 && transmit_weight <= 0.0 {
            return colour;
        }
        let choice = self.choose(s.path.block(), reflect_weight, transmit_weight, sampler);
        if let Some(p) = choice.reflect
            && let Some(c) = self.reflected(s, &b, top.finish, p, sampler, counts)
        {
            colour += c;
        }
        if let Some(p) = choice.transmit
            && let Some(c) = self.transmitted(s, &b, p, sampler, counts)
        {
            colour += c;
        }
        colour
    }

    /// Both branches, or under `--splitting one` one of them at random in proportion to
    /// its weight (`block`: the hit's dimension block).
    fn choose(
        &self,
        block: u32,
        reflect: f64,
        transmit: f64,
        sampler: &mut PixelSampler,
    ) -> Choice {
        let mut choice = Choice {
            reflect: (reflect > 0.0).then_some(1.0),
            transmit: (transmit > 0.0).then_some(1.0),
        };
        if self.splitting == Splitting::One && choice.reflect.is_some() && choice.transmit.is_some()
        {
            sampler.set_dimension(self.layout.dimension(block, Purpose::Splitting));
            let u = sampler.get_1d();
            let pr = reflect / (reflect + transmit);
            if u < pr {
                choice = Choice {
                    reflect: Some(pr),
                    transmit: None,
                };
            } else {
                choice = Choice {
                    reflect: None,
                    transmit: Some(1.0 - pr),
                };
            }
        }
        choice
    }

    /// The mirror reflection, chosen with probability `chosen`; `None` where roulette ends it.
    fn reflected(
        &self,
        s: &Shading,
        b: &Branches,
        finish: &Finish,
        chosen: f64,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> Option<DVec3> {
        let e = finish.reflection.exponent;
        let branch = Branch {
            dir: b.mirror,
            level: s.path.level + 1,
            skip: flags::NO_REFLECTION,
            interiors: s.path.interiors,
            wavelength: s.path.wavelength,
            weight: s.path.weight * b.reflect.abs().max_element() / chosen,
            linear: e == 1.0,
            roulette: Purpose::RouletteReflection,
        };
        let (incoming, q) = self.follow(s, &branch, sampler, counts)?;
        let incoming = if e == 1.0 {
            incoming
        } else {
            incoming.max(DVec3::ZERO).powf(1.0 / e)
        };
        Some(b.reflect * incoming / (q * chosen))
    }

    /// The transmitted light, chosen with probability `chosen`; `None` where roulette ends
    /// it. An index of refraction of 1 goes on straight without counting a trace level;
    /// total internal reflection sends the transmitted part along the mirror direction.
    fn transmitted(
        &self,
        s: &Shading,
        b: &Branches,
        chosen: f64,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> Option<DVec3> {
        let path = &s.path;
        let (b, wavelength) = self.disperse(s, b, sampler);
        let (dir, level, interiors, skip) = match b.refracted {
            Some(_) if b.straight => (s.d, path.level, b.beyond, path.skip),
            Some(dir) => (dir, path.level + 1, b.beyond, path.skip & !flags::NO_IMAGE),
            None => (b.mirror, path.level + 1, path.interiors, path.skip),
        };
        let branch = Branch {
            dir,
            level,
            skip,
            interiors,
            wavelength,
            weight: path.weight * b.transmit.abs().max_element() / chosen,
            linear: true,
            roulette: Purpose::RouletteTransmission,
        };
        let (incoming, q) = self.follow(s, &branch, sampler, counts)?;
        Some(b.transmit * incoming / (q * chosen))
    }

    /// Traces a branch from the hit after roulette: the light coming back along it and
    /// the survival probability it must be divided by, or `None` where roulette ends it.
    fn follow(
        &self,
        s: &Shading,
        branch: &Branch,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> Option<(DVec3, f64)> {
        let q = self.survival(branch.weight, branch.linear, branch.level);
        if q <= 0.0 || !self.survives(q, s.path.block(), branch.roulette, sampler) {
            return None;
        }
        let origin = offset_point(s.surface.point, s.surface.normal, branch.dir);
        counts.secondary += 1;
        let next = Path {
            level: branch.level,
            weight: branch.weight / q,
            skip: branch.skip,
            interiors: branch.interiors,
            wavelength: branch.wavelength,
            bounces: s.path.bounces,
        };
        Some((
            self.trace(&Ray::new(origin, branch.dir), next, sampler, counts),
            q,
        ))
    }

    /// What a ray that leaves the scene sees: the sky sphere's pigments, layered over the
    /// background through their filter and transmit.
    fn sky(&self, direction: DVec3) -> DVec3 {
        let scene = self.scene;
        let Some(sky) = &scene.sky_sphere else {
            return scene.background.rgb;
        };
        let d = direction.normalize_or(DVec3::Z);
        sky_colour(sky, d, scene.background.rgb, scene.legacy)
    }

    /// The probability a branch of this weight at this level is traced: roulette's below
    /// its threshold where the branch enters linearly, 0 below adc_bailout where the tree
    /// ends as POV-Ray's, 1 otherwise.
    fn survival(&self, weight: f64, linear: bool, level: u32) -> f64 {
        if weight <= 0.0 {
            return 0.0;
        }
        let threshold = if level <= SHALLOW_LEVELS {
            ROULETTE_WEIGHT
        } else {
            DEEP_ROULETTE_WEIGHT
        };
        match self.termination {
            Termination::Roulette if linear && weight < threshold => {
                (weight / threshold).max(ROULETTE_MIN_Q)
            }
            Termination::AdcBailout if weight < self.scene.settings.adc_bailout => 0.0,
            _ => 1.0,
        }
    }

    fn survives(&self, q: f64, block: u32, purpose: Purpose, sampler: &mut PixelSampler) -> bool {
        if q >= 1.0 {
            return true;
        }
        sampler.set_dimension(self.layout.dimension(block, purpose));
        sampler.get_1d() < q
    }
}

/// The interiors of the objects whose solid holds the camera (in no particular order:
/// containers nested around the camera are rare).
fn camera_interiors(scene: &PreparedScene) -> InteriorStack {
    interiors_at(scene, scene.camera.location)
}

/// The interiors of the objects whose solid holds a point (a camera, or a light its
/// photons leave).
fn interiors_at(scene: &PreparedScene, point: DVec3) -> InteriorStack {
    scene
        .world
        .containing(point)
        .fold(InteriorStack::OUTSIDE, |stack, material| {
            let m = &scene.materials[material as usize];
            stack.entered(m.interior_id, m.interior.ior, m.hollow)
        })
}

/// The directions and weights of the reflected and transmitted branches at a hit.
fn branches(s: &Shading, top: &Top) -> Branches {
    let (eta_from, eta_to, beyond) = crossing(s);
    let (d, n, geometric) = (s.d, s.n, s.surface.normal);
    let cos_i = -d.dot(n);
    let outside = if geometric.dot(d) > 0.0 {
        -geometric
    } else {
        geometric
    };
    let mirror = mirror_direction(d, n, outside);
    let eta = eta_from / eta_to;
    let straight = (eta - 1.0).abs() < 1e-12;
    // (Opaque surfaces transmit nothing: no refraction to compute.)
    let refracted = if straight || top.through == DVec3::ZERO {
        Some(d)
    } else {
        refract(d, n, eta)
    };
    let fresnel_side = if s.leaving && refracted.is_some() && !beyond.is_empty() {
        FresnelSide::IntoOuterInterior
    } else {
        FresnelSide::Other
    };
    // `reflection { metallic }` tints the reflection as `metallic` tints highlights.
    let reflect = surface_reflectivity(top.finish, cos_i, (eta_from, eta_to), fresnel_side)
        * metallic_tint(top.finish.reflection.metallic, top.pigment.rgb, cos_i);
    let total_internal = refracted.is_none();
    let transmit = transmitted_weight(
        top.through,
        s.fade_through,
        reflect,
        total_internal,
        top.finish.conserve_energy,
    );
    let reflect = internally_reflected(
        reflect,
        top.through,
        s.fade_through,
        (total_internal, beyond.is_empty()),
        top.finish.conserve_energy,
    );
    Branches {
        mirror,
        reflect,
        refracted,
        straight,
        transmit,
        beyond,
    }
}

/// Indices of refraction on the ray's side and beyond the surface, and the interiors beyond.
fn crossing(s: &Shading) -> (f64, f64, InteriorStack) {
    crossing_at(s, s.path.wavelength)
}

/// [`crossing`] for a ray of wavelength parameter `wavelength`.
fn crossing_at(s: &Shading, wavelength: Option<f64>) -> (f64, f64, InteriorStack) {
    let id = s.material.interior_id;
    let ior = dispersion::interior_ior(s.material, wavelength);
    let inside = &s.path.interiors;
    if s.leaving {
        // Leaving means the ray is in this interior (see `shading`).
        let beyond = inside.left(id);
        (ior, beyond.current(), beyond)
    } else {
        (
            inside.current(),
            ior,
            inside.entered(id, ior, s.material.hollow),
        )
    }
}

/// Where a ray meets a surface, as far as `fresnel` is concerned.
#[derive(Clone, Copy, PartialEq, Eq)]
enum FresnelSide {
    /// Leaving an interior, where the light could cross, into another object's interior
    /// (a glass in a closed room).
    IntoOuterInterior,
    Other,
}

/// Per-channel reflectivity: `reflection {min, max falloff}`, or Fresnel for light going
/// from a medium of index `eta_from` into one of `eta_to`. A ray leaving an interior into
/// another object's interior, where it could cross, gets fresnel's 0 (the reflectivity
/// `min`), not Fresnel's inner reflectance; into the atmosphere it gets the inner
/// reflectance. Measured on a glass prism (ior 1.5, faded, so that the unfaded internal
/// reflection shows) met from inside at 15 to 41 degrees: inside a sphere round the scene or
/// in front of a plane whose inside holds it, `reflection { 0, 1 fresnel on }` renders as no
/// reflection and `{ 0.1, 1 fresnel on }` as `reflection 0.1`, to 1e-4; in the open, as the
/// equations give (and scenes/glass.pov's sphere needs). Beyond the critical angle fresnel
/// gives `max` either way.
fn surface_reflectivity(
    finish: &Finish,
    cos_i: f64,
    (eta_from, eta_to): (f64, f64),
    side: FresnelSide,
) -> DVec3 {
    let refl = &finish.reflection;
    if refl.is_zero() {
        return DVec3::ZERO;
    }
    if refl.fresnel {
        let f = match side {
            FresnelSide::IntoOuterInterior => 0.0,
            FresnelSide::Other => fresnel(cos_i.abs(), eta_to / eta_from),
        };
        return f * refl.max + (1.0 - f) * refl.min;
    }
    reflectivity(refl.min, refl.max, refl.falloff, cos_i)
}

/// The weight of the transmitted branch, from what the layers let through, the interior's
/// fade and the reflectivity `r`. Under total internal reflection the light does not
/// cross the surface: POV-Ray reflects all of it, the finish's reflection plus the rest
/// along the same mirror direction, unfiltered by the surface's colour (measured on a glass
/// box: filter 0.5 without reflection is exactly 2x and 4x brighter than the filtered
/// estimate where rays reflect totally once and twice; with reflection 0.1 the two add to 1).
/// With conserve_energy, what is reflected is not also transmitted.
fn transmitted_weight(
    through: DVec3,
    fade: DVec3,
    r: DVec3,
    total_internal: bool,
    conserve_energy: bool,
) -> DVec3 {
    if through == DVec3::ZERO {
        through
    } else if total_internal {
        (DVec3::ONE - r).max(DVec3::ZERO) * fade
    } else if conserve_energy {
        through * fade * (DVec3::ONE - r)
    } else {
        through * fade
    }
}

/// The weight of the reflected branch. A surface left from inside reflects unfaded, but
/// under total internal reflection POV-Ray fades the finish's reflection too, with the
/// rest, by the stretch just travelled. One exception: where conserve_energy leaves nothing
/// to transmit (fresnel's reflectivity 1) and beyond the surface is no interior at all (the
/// atmosphere), only the reflection, unfaded, remains. Measured on glass prisms (ior 1.5,
/// exponential fade) met by one and by two total reflections: the unfaded rule holds to 2e-3
/// for a prism in the open, with the stretches split three ways; the same prism inside any
/// other object (a sphere round it, hollow or not, or a plane behind it, whose inside holds
/// the scene) fades the whole path (0.3932 against 0.6222 for fresnel with conserve_energy).
fn internally_reflected(
    reflect: DVec3,
    through: DVec3,
    fade: DVec3,
    (total_internal, into_atmosphere): (bool, bool),
    conserve_energy: bool,
) -> DVec3 {
    let would_transmit = if conserve_energy {
        through * (DVec3::ONE - reflect).max(DVec3::ZERO)
    } else {
        through
    };
    if !total_internal || (would_transmit == DVec3::ZERO && into_atmosphere) {
        reflect
    } else {
        reflect * fade
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn total_internal_reflection_fades_unless_nothing_would_transmit() {
        let (through, fade) = (DVec3::ONE, DVec3::splat(0.5));
        let r = DVec3::splat(0.2);
        // Leaving without total internal reflection: the reflection is not faded.
        let open = (true, true);
        assert_eq!(
            internally_reflected(r, through, fade, (false, true), true),
            r
        );
        assert_eq!(internally_reflected(r, through, fade, open, false), r * 0.5);
        assert_eq!(internally_reflected(r, through, fade, open, true), r * 0.5);
        // Fresnel's reflectivity 1: faded without conserve_energy, not with it, unless
        // the surface leads into another interior.
        let all = DVec3::ONE;
        assert_eq!(internally_reflected(all, through, fade, open, false), fade);
        assert_eq!(internally_reflected(all, through, fade, open, true), all);
        assert_eq!(
            internally_reflected(all, through, fade, (true, false), true),
            fade
        );
    }

    #[test]
    fn transmission_keeps_what_is_not_reflected() {
        let through = DVec3::new(0.8, 0.4, 0.0);
        let fade = DVec3::splat(0.5);
        let r = DVec3::splat(0.25);
        assert_eq!(
            transmitted_weight(through, fade, r, false, false),
            through * 0.5
        );
        assert_eq!(
            transmitted_weight(through, fade, r, false, true),
            through * 0.5 * 0.75
        );
        // Total internal reflection: all that is not reflected goes the mirror way,
        // unfiltered by the surface colour.
        assert_eq!(
            transmitted_weight(through, fade, r, true, false),
            DVec3::splat(0.75 * 0.5)
        );
        assert_eq!(
            transmitted_weight(DVec3::ZERO, fade, r, true, true),
            DVec3::ZERO
        );
    }

    #[test]
    fn fresnel_reflection_blends_min_and_max() {
        let mut finish = Finish::default();
        finish.reflection.min = DVec3::ZERO;
        finish.reflection.max = DVec3::ONE;
        finish.reflection.fresnel = true;
        // Normal incidence from air into glass: 4%.
        let r = surface_reflectivity(&finish, 1.0, (1.0, 1.5), FresnelSide::Other);
        assert!((r - DVec3::splat(0.04)).length() < 1e-12, "{r}");
        // Beyond the critical angle inside glass: all of it.
        let r = surface_reflectivity(&finish, 0.2, (1.5, 1.0), FresnelSide::Other);
        assert!((r - DVec3::ONE).length() < 1e-12, "{r}");
        // Leaving glass into another interior where the light could cross: POV-Ray's
        // fresnel gives min.
        finish.reflection.min = DVec3::splat(0.1);
        let r = surface_reflectivity(&finish, 0.9, (1.5, 1.0), FresnelSide::IntoOuterInterior);
        assert_eq!(r, DVec3::splat(0.1));
    }

    #[test]
    fn roulette_survival_is_bounded_and_only_for_low_weights() {
        let scene = PreparedScene::new(&crate::scene::Scene::default());
        let on = Integrator::new(&scene, &RenderOptions::default());
        // Within the first five levels roulette starts at 0.01, deeper at 0.1.
        let (shallow, deep) = (SHALLOW_LEVELS, SHALLOW_LEVELS + 1);
        assert_eq!(on.survival(0.5, true, shallow), 1.0);
        assert_eq!(on.survival(0.05, true, shallow), 1.0);
        assert_eq!(on.survival(0.005, true, shallow), 0.5);
        assert_eq!(on.survival(0.05, true, deep), 0.5);
        assert_eq!(on.survival(1e-6, true, shallow), ROULETTE_MIN_Q);
        assert_eq!(on.survival(1e-6, true, deep), ROULETTE_MIN_Q);
        assert_eq!(on.survival(0.005, false, shallow), 1.0);
        assert_eq!(on.survival(0.0, true, shallow), 0.0);
        let off = Integrator::new(
            &scene,
            &RenderOptions {
                roulette: false,
                ..RenderOptions::default()
            },
        );
        assert_eq!(off.survival(1e-6, true, deep), 1.0);
        let mut gamma = PreparedScene::new(&crate::scene::Scene::default());
        gamma.output_gamma = Some(crate::render::prepared::GammaDecode::Power(2.2));
        let cut = Integrator::new(&gamma, &RenderOptions::default());
        assert_eq!(cut.survival(0.05, true, deep), 1.0);
        assert_eq!(cut.survival(0.001, true, shallow), 0.0);
    }

    /// A plane under `light`, shaded along one ray from above at sample `index` of `spp` by
    /// the integrator with one shadow ray per area light (a one-ray pixel's with
    /// `one_ray`) of a render of one sample per pixel (`spp` with `budget`): the colour
    /// and the shadow rays sent.
    fn shade_floor(
        light: &str,
        (index, spp): (u32, u32),
        one_ray: bool,
        budget: bool,
    ) -> (DVec3, u64) {
        let texture = "pigment { rgb 0.8 } finish { phong 0.6 }";
        shade_textured_floor(texture, light, (index, spp), one_ray, budget)
    }

    /// [`shade_floor`] with the plane's `texture`.
    fn shade_textured_floor(
        texture: &str,
        light: &str,
        (index, spp): (u32, u32),
        one_ray: bool,
        budget: bool,
    ) -> (DVec3, u64) {
        let src = format!("plane {{ y, 0 {texture} }} {light}");
        let loaded = crate::lang::load_scene_source("t.pov", &src, &Default::default());
        let scene = PreparedScene::new(&loaded.expect("scene loads").scene);
        let options = RenderOptions {
            light_samples: LightSamples::Fixed(1),
            samples_per_pixel: if budget { spp } else { 1 },
            ..RenderOptions::default()
        };
        let integrator = Integrator::new(&scene, &options);
        let integrator = if one_ray {
            integrator.one_ray()
        } else {
            integrator
        };
        let ray = Ray::new(DVec3::new(0.3, 2.0, -3.0), DVec3::new(0.0, -2.0, 3.0));
        let (mut sampler, mut counts) = (PixelSampler::new(spp), RayCounts::default());
        sampler.start(1, 2, index, 9);
        let colour = integrator.radiance(&ray, &mut sampler, &mut counts);
        (colour, counts.shadow)
    }

    /// A layered texture's layers share the shadow rays of each light: one for a point
    /// light and one per light sample for a jittered area light, as for one layer (the
    /// shadow does not depend on the layer; POV-Ray tests a light once per point).
    #[test]
    fn texture_layers_share_their_shadow_rays() {
        let one = "pigment { rgb 0.8 } finish { phong 0.6 }";
        let two = "texture { pigment { rgb 0.8 } }
            texture { pigment { rgbt <0.9, 0.2, 0.1, 0.5> } finish { phong 0.6 } }";
        for light in [
            "light_source { <0, 5, 0> rgb 1 }",
            "light_source { <0, 5, 0> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 4, 4 jitter }",
        ] {
            let (single, single_rays) = shade_textured_floor(one, light, (0, 1), false, false);
            let (layered, layered_rays) = shade_textured_floor(two, light, (0, 1), false, false);
            assert!(single_rays >= 1, "{light}: no shadow ray");
            assert_eq!(layered_rays, single_rays, "{light}");
            assert!(
                layered.x > single.x && layered.z < single.z,
                "{layered} {single}"
            );
        }
    }

    /// Under a fully visible `adaptive` area light, POV-Ray's rule would find the grid's
    /// corners agreeing; nothing meets the shaft from the floor to the light, so it needs
    /// no ray at all. A one-ray pixel's integrator sends one shadow ray instead, and both
    /// see the same light.
    #[test]
    fn one_ray_pixels_take_one_shadow_ray_for_an_adaptive_light() {
        let light = "light_source { <0, 5, 0> rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 9, 9
            adaptive 1 }";
        let (rule, rule_rays) = shade_floor(light, (0, 1), false, false);
        let (one, one_rays) = shade_floor(light, (0, 1), true, false);
        assert_eq!(rule_rays, 0, "an empty shaft");
        assert_eq!(one_rays, 1);
        assert!(
            (one - rule).abs().max_element() < 1e-12,
            "{one} against {rule}"
        );
        assert!(one.x > 0.1, "lit: {one}");
    }

    /// A one-ray pixel shades a small area_illumination grid whole: every sample sees the
    /// grid's average, where a sample elsewhere shades a few points spread over it in a
    /// render of one sample per pixel; from 1.25 samples per pixel on, every sample shades
    /// it whole.
    #[test]
    fn one_ray_pixels_shade_a_small_grid_whole() {
        let light = "light_source { <0, 2, 0> rgb 1 area_light <6, 0, 0>, <0, 0, 2>, 7, 3
            area_illumination on }";
        let first = shade_floor(light, (0, 8), true, false).0;
        for index in 1..8 {
            for (one_ray, budget) in [(true, false), (true, true), (false, true)] {
                let c = shade_floor(light, (index, 8), one_ray, budget).0;
                assert_eq!(c, first, "sample {index}, {one_ray} {budget}");
            }
        }
        let spread: Vec<DVec3> = (0..8)
            .map(|i| shade_floor(light, (i, 8), false, false).0)
            .collect();
        assert!(spread.iter().any(|&c| c != spread[0]), "{spread:?}");
        // The spread samples average to the grid's whole shading: 8 samples of 7 points
        // cover each of the 21 two or three times, which leaves 0.08% here.
        let mean = spread.iter().sum::<DVec3>() / 8.0;
        assert!(
            (mean - first).abs().max_element() < 0.01 * first.max_element(),
            "{mean} {first}"
        );
    }

    #[test]
    fn dimensions_depend_on_the_lights_not_the_objects() {
        let scene = |spheres: usize, lights: usize| {
            let mut src = String::new();
            for i in 0..spheres {
                src += &format!("sphere {{ <{i}, 0, 0>, 0.4 pigment {{ rgb 1 }} }}\n");
            }
            for i in 0..lights {
                src += &format!("light_source {{ <{i}, 5, -5> rgb 1 }}\n");
            }
            let loaded = crate::lang::load_scene_source("t.pov", &src, &Default::default());
            PreparedScene::new(&loaded.expect("scene loads").scene)
        };
        let options = RenderOptions::default();
        let (one, many) = (scene(1, 2), scene(200, 2));
        let a = *Integrator::new(&one, &options).layout();
        let b = *Integrator::new(&many, &options).layout();
        assert_eq!(a, b);
        let other = scene(1, 3);
        assert_ne!(a, *Integrator::new(&other, &options).layout());
        for level in 1..=one.settings.max_trace_level {
            for p in a.level_purposes() {
                assert_eq!(a.dimension(level, p), b.dimension(level, p));
            }
        }
    }
}
