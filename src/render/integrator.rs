//! The integrator answers one question: what radiance comes back along a ray. It is
//! POV-Ray's recursive Whitted tracer (ambient, diffuse, highlights, shadow rays through
//! filtering objects, mirror reflection, refraction) with stochastic changes that keep
//! POV-Ray's expectation: area-light visibility is estimated from one grid point drawn with
//! POV-Ray's weights, the deterministic adc_bailout cut is replaced by Russian roulette
//! (expectation: the max_trace_level-capped tree), and where a surface both reflects and
//! refracts, one branch may be chosen at random in proportion to its weight.

use glam::DVec3;

use crate::appearance::finish::{
    diffuse_term, metallic_tint, phong_factor, reflectivity, specular_factor,
};
use crate::appearance::{evaluate_pigment, perturbed_normal, texture_layers};
use crate::geometry::{Ray, SurfacePoint, flags, offset_point};
use crate::scene::{Colour, Finish};

use super::lights::AreaLightMode;
use super::prepared::{Material, PreparedScene};
use super::sampler::PixelSampler;

/// Spreads several light samples: point k of n is shifted by (k/n, k * golden ratio mod 1),
/// a well-spread 2D set for any n.
const GOLDEN: f64 = 0.618_033_988_749_894_9;

/// Below this path weight, Russian roulette starts.
const ROULETTE_WEIGHT: f64 = 0.1;
/// The smallest survival probability, which bounds the variance roulette can add.
const ROULETTE_MIN_Q: f64 = 0.05;
/// Nested media deeper than this are treated as the innermost one.
const MEDIA_DEPTH: usize = 8;

/// Rays traced, by kind, for the statistics line.
#[derive(Clone, Copy, Debug, Default)]
pub struct RayCounts {
    pub camera: u64,
    pub shadow: u64,
    pub secondary: u64,
}

impl RayCounts {
    pub fn add(&mut self, o: &RayCounts) {
        self.camera += o.camera;
        self.shadow += o.shadow;
        self.secondary += o.secondary;
    }

    pub fn total(&self) -> u64 {
        self.camera + self.shadow + self.secondary
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

/// The interiors a ray is inside, innermost last, with their indices of refraction. POV-Ray
/// keeps interiors, not surfaces: a ray inside an interior that meets any part of the object
/// owning it leaves that interior, whichever way the part faces (measured: a glass box and a
/// cylinder of one object meeting face to face, or overlapping, turn a ray back by total
/// internal reflection at the box's top as if air were beyond, exactly as with a gap).
#[derive(Clone, Copy, Debug)]
struct Media {
    ids: [u32; MEDIA_DEPTH],
    iors: [f64; MEDIA_DEPTH],
    len: usize,
}

impl Media {
    const OUTSIDE: Media = Media {
        ids: [u32::MAX; MEDIA_DEPTH],
        iors: [1.0; MEDIA_DEPTH],
        len: 0,
    };

    fn current(&self) -> f64 {
        if self.len == 0 {
            1.0
        } else {
            self.iors[self.len - 1]
        }
    }

    fn contains(&self, id: u32) -> bool {
        self.ids[..self.len].contains(&id)
    }

    fn entered(&self, id: u32, ior: f64) -> Media {
        let mut m = *self;
        let slot = m.len.min(MEDIA_DEPTH - 1);
        m.ids[slot] = id;
        m.iors[slot] = ior;
        m.len = slot + 1;
        m
    }

    /// Without the interior `id` (the innermost one when the ray did not know it was in it,
    /// as a camera inside an object).
    fn left(&self, id: u32) -> Media {
        let mut m = *self;
        match m.ids[..m.len].iter().rposition(|&i| i == id) {
            Some(k) => {
                m.ids.copy_within(k + 1..m.len, k);
                m.iors.copy_within(k + 1..m.len, k);
                m.len -= 1;
            }
            None => m.len = m.len.saturating_sub(1),
        }
        m
    }
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
    media: Media,
}

pub struct Integrator<'a> {
    scene: &'a PreparedScene,
    /// Sampler dimensions per trace level: two per light, then roulette and splitting.
    dims_per_level: u32,
    pub roulette: bool,
    pub splitting: Splitting,
    pub area_lights: AreaLightMode,
    /// Shadow rays per area light per shading point (more where soft shadows dominate the
    /// noise; each camera sample then costs more).
    pub light_samples: u32,
    /// Dimensions before the path's own: the pixel position (2) and the lens (2).
    first_path_dimension: u32,
}

/// Per light and level: the shadow-test point (2) and, for area_illumination, the shading
/// point (2).
const DIMS_PER_LIGHT: u32 = 4;
/// Per level after the lights: roulette for reflection and transmission, and splitting.
const EXTRA_DIMS: u32 = 3;

impl<'a> Integrator<'a> {
    pub fn new(scene: &'a PreparedScene) -> Integrator<'a> {
        Integrator {
            scene,
            dims_per_level: DIMS_PER_LIGHT * scene.lights.len() as u32 + EXTRA_DIMS,
            roulette: true,
            splitting: Splitting::default(),
            area_lights: AreaLightMode::Pov,
            light_samples: 1,
            first_path_dimension: 4,
        }
    }

    /// Radiance along a camera ray.
    pub fn radiance(&self, ray: &Ray, sampler: &mut PixelSampler, counts: &mut RayCounts) -> DVec3 {
        counts.camera += 1;
        let path = Path {
            level: 1,
            weight: 1.0,
            skip: flags::NO_IMAGE,
            media: Media::OUTSIDE,
        };
        let l = self.trace(ray, path, sampler, counts);
        match self.scene.output_gamma {
            // Per sample, as POV-Ray decodes each traced ray; where the estimate is noisy
            // (area lights) the curve's bend adds a small bias (docs/differences.md).
            Some(g) => l.map(|c| g.decode(c)),
            None => l,
        }
    }

    fn dimension(&self, level: u32, slot: u32) -> u32 {
        self.first_path_dimension + (level - 1) * self.dims_per_level + slot
    }

    fn trace(
        &self,
        ray: &Ray,
        path: Path,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let scene = self.scene;
        let Some(hit) = scene.world.intersect(ray, f64::INFINITY, path.skip) else {
            return self.sky(ray.direction);
        };
        let surface = scene.world.surface(ray, &hit);
        let material = &scene.materials[surface.material as usize];
        let d = ray.direction.normalize();
        // The ray meets the surface from behind, and whether it leaves the interior (see
        // Media: the two differ where parts of one object touch or overlap).
        let back = surface.normal.dot(d) > 0.0;
        let leaving = back || path.media.contains(material.interior_id);
        // A ray that crossed this object's interior to get here fades, but only in what the
        // surface lets through from beyond: POV-Ray leaves the surface's own shading (its
        // highlights seen from inside) and its internal reflection unfaded (measured: a
        // transparent sphere's inner highlight keeps its full strength at fade_power 0, whose
        // fade halves what is seen through the sphere; shadow rays do not fade at power 0).
        let fade_through = if leaving && material.interior.fade_distance > 0.0 {
            fade(material, hit.t * ray.direction.length())
        } else {
            DVec3::ONE
        };
        self.shade(
            d,
            &surface,
            material,
            path,
            back,
            leaving,
            fade_through,
            sampler,
            counts,
        )
    }

    #[allow(clippy::too_many_arguments)]
    fn shade(
        &self,
        d: DVec3,
        surface: &SurfacePoint,
        material: &Material,
        path: Path,
        back: bool,
        leaving: bool,
        fade_through: DVec3,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let scene = self.scene;
        let p = surface.point;
        let geometric = surface.normal;
        let texture = &material.texture;
        // The shading normal, turned to face the incoming ray.
        let facing = if back {
            -surface.shading_normal
        } else {
            surface.shading_normal
        };
        let n = perturbed_normal(texture, surface, facing);
        let layers = texture_layers(texture, surface);
        let mut colour = DVec3::ZERO;
        // Layers composite top first: each lets through what its own opacity does not cover.
        let mut through = DVec3::ONE;
        let mut top: Option<(Colour, &Finish)> = None;
        for layer in layers.iter() {
            let c = layer.colour;
            let att = c.opacity(scene.legacy);
            let lit = self.surface_light(
                p,
                d,
                n,
                geometric,
                c,
                layer.finish,
                att,
                material,
                path.level,
                sampler,
                counts,
            );
            colour += through * lit;
            if top.is_none() {
                top = Some((c, layer.finish));
            }
            through *= c.rgb * c.filter + DVec3::splat(c.transmit);
            if through == DVec3::ZERO {
                break;
            }
        }
        let Some((top_colour, finish)) = top else {
            return colour;
        };
        if path.level >= scene.settings.max_trace_level {
            return colour;
        }
        // Indices of refraction on the ray's side and beyond the surface.
        let id = material.interior_id;
        let ior = material.interior.ior;
        let (eta_from, eta_to, beyond) = if leaving {
            let beyond = path.media.left(id);
            let from = if path.media.contains(id) {
                ior
            } else {
                path.media.current()
            };
            (from, beyond.current(), beyond)
        } else {
            (path.media.current(), ior, path.media.entered(id, ior))
        };
        let cos_i = -d.dot(n);
        let outside = if geometric.dot(d) > 0.0 {
            -geometric
        } else {
            geometric
        };
        let mirror = mirror_direction(d, n, outside);
        // `reflection { metallic }` tints the reflection as `metallic` tints highlights.
        let r = self.reflectivity(finish, cos_i, eta_from, eta_to)
            * metallic_tint(finish.reflection.metallic, top_colour.rgb, cos_i);
        let eta = eta_from / eta_to;
        let straight = (eta - 1.0).abs() < 1e-12;
        // (Opaque surfaces transmit nothing: no refraction to compute.)
        let refracted = if straight || through == DVec3::ZERO {
            Some(d)
        } else {
            refract(d, n, eta)
        };
        // Under total internal reflection the light does not cross the surface: POV-Ray
        // reflects all of it, the finish's reflection plus the rest along the same mirror
        // direction, unfiltered by the surface's colour (measured on a glass box: filter 0.5
        // without reflection is exactly 2x and 4x brighter than the filtered estimate where
        // rays reflect totally once and twice; with reflection 0.1 the two add to 1).
        let transmit = if through == DVec3::ZERO {
            through
        } else if refracted.is_none() {
            (DVec3::ONE - r).max(DVec3::ZERO) * fade_through
        } else if finish.conserve_energy {
            // What the layers let through, less what is reflected.
            through * fade_through * (DVec3::ONE - r)
        } else {
            through * fade_through
        };
        let reflect_weight = r.max_element();
        let transmit_weight = transmit.max_element();
        if reflect_weight <= 0.0 && transmit_weight <= 0.0 {
            return colour;
        }
        // Choose which branches to follow.
        let (mut follow_reflect, mut follow_transmit) =
            (reflect_weight > 0.0, transmit_weight > 0.0);
        let (mut p_reflect, mut p_transmit) = (1.0, 1.0);
        if self.splitting == Splitting::One && follow_reflect && follow_transmit {
            sampler.set_dimension(self.dimension(path.level, self.dims_per_level - 1));
            let u = sampler.get_1d();
            let pr = reflect_weight / (reflect_weight + transmit_weight);
            if u < pr {
                follow_transmit = false;
                p_reflect = pr;
            } else {
                follow_reflect = false;
                p_transmit = 1.0 - pr;
            }
        }
        if follow_reflect {
            let weight = path.weight * reflect_weight / p_reflect;
            let q = self.survival(weight, finish.reflection.exponent == 1.0);
            if q > 0.0 && self.survives(q, path.level, 0, sampler) {
                let reflected = Ray::new(offset_point(p, geometric, mirror), mirror);
                counts.secondary += 1;
                let next = Path {
                    level: path.level + 1,
                    weight: weight / q,
                    skip: flags::NO_REFLECTION,
                    media: path.media,
                };
                let incoming = self.trace(&reflected, next, sampler, counts);
                let e = finish.reflection.exponent;
                let incoming = if e == 1.0 {
                    incoming
                } else {
                    incoming.max(DVec3::ZERO).powf(1.0 / e)
                };
                colour += r * incoming / (q * p_reflect);
            }
        }
        if follow_transmit {
            let weight = path.weight * transmit_weight / p_transmit;
            let q = self.survival(weight, true);
            if q > 0.0 && self.survives(q, path.level, 1, sampler) {
                // ior 1 continues straight and does not count a trace level; total internal
                // reflection sends the transmitted part along the mirror direction.
                let (dir, level, media, skip) = match refracted {
                    Some(_) if straight => (d, path.level, beyond, path.skip),
                    Some(dir) => (dir, path.level + 1, beyond, path.skip & !flags::NO_IMAGE),
                    None => (mirror, path.level + 1, path.media, path.skip),
                };
                let ray = Ray::new(offset_point(p, geometric, dir), dir);
                counts.secondary += 1;
                let next = Path {
                    level,
                    weight: weight / q,
                    skip,
                    media,
                };
                let incoming = self.trace(&ray, next, sampler, counts);
                colour += transmit * incoming / (q * p_transmit);
            }
        }
        colour
    }

    /// What a ray that leaves the scene sees: the sky sphere's pigments, layered over the
    /// background through their filter and transmit.
    fn sky(&self, direction: DVec3) -> DVec3 {
        let scene = self.scene;
        let Some(sky) = &scene.sky_sphere else {
            return scene.background.rgb;
        };
        let d = direction.normalize_or(DVec3::Z);
        let mut colour = scene.background.rgb;
        for pigment in &sky.pigments {
            let c = evaluate_pigment(pigment, d);
            let att = c.opacity(scene.legacy);
            colour =
                c.rgb * att * sky.emission + colour * (c.rgb * c.filter + DVec3::splat(c.transmit));
        }
        colour
    }

    /// Roulette's survival probability for a branch of this weight (1 when roulette is off,
    /// the weight is large, or the branch enters non-linearly).
    fn survival(&self, weight: f64, linear: bool) -> f64 {
        if weight <= 0.0 {
            return 0.0;
        }
        if self.roulette && linear && weight < ROULETTE_WEIGHT {
            (weight / ROULETTE_WEIGHT).max(ROULETTE_MIN_Q)
        } else {
            1.0
        }
    }

    fn survives(&self, q: f64, level: u32, branch: u32, sampler: &mut PixelSampler) -> bool {
        if q >= 1.0 {
            return true;
        }
        let lights = DIMS_PER_LIGHT * self.scene.lights.len() as u32;
        sampler.set_dimension(self.dimension(level, lights + branch));
        sampler.get_1d() < q
    }

    /// Per-channel reflectivity: `reflection {min, max falloff}`, or Fresnel for light
    /// going from a medium of index `eta_from` into one of `eta_to`.
    fn reflectivity(&self, finish: &Finish, cos_i: f64, eta_from: f64, eta_to: f64) -> DVec3 {
        let refl = &finish.reflection;
        if refl.is_zero() {
            return DVec3::ZERO;
        }
        if refl.fresnel {
            let f = fresnel(cos_i.abs(), eta_to / eta_from);
            return f * refl.max + (1.0 - f) * refl.min;
        }
        reflectivity(refl.min, refl.max, refl.falloff, cos_i)
    }

    /// Ambient, emission and the direct light from every light source.
    #[allow(clippy::too_many_arguments)]
    fn surface_light(
        &self,
        p: DVec3,
        d: DVec3,
        n: DVec3,
        geometric: DVec3,
        pigment: Colour,
        finish: &Finish,
        att: f64,
        material: &Material,
        level: u32,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let scene = self.scene;
        let c = pigment.rgb;
        let mut colour = c * finish.ambient * scene.settings.ambient_light * att;
        colour += c * finish.emission * att;
        let origin = offset_point(p, geometric, -d);
        for (index, light) in scene.lights.iter().enumerate() {
            let incidence = match &light.area {
                // Shading from one grid point, drawn with equal weights, independently of
                // the shadow test: the product of the average shading and the visibility.
                Some(area) if light.area_illumination => {
                    sampler.set_dimension(self.dimension(level, DIMS_PER_LIGHT * index as u32 + 2));
                    let towards = light.location - p;
                    let at = area.sample_point(
                        light.location,
                        sampler.get_2d(),
                        towards,
                        self.area_lights,
                        true,
                    );
                    light.incidence_from(p, at)
                }
                _ => light.incidence(p),
            };
            let Some(incidence) = incidence else {
                continue;
            };
            let (l, distance) = (incidence.l, incidence.distance);
            let mut n_dot_l = n.dot(l);
            // A double-illuminated surface lit from behind: its shadow ray starts on the
            // light's side, or it would cross the surface it leaves.
            let mut origin = origin;
            if n_dot_l <= 0.0 {
                if !material.double_illuminate {
                    continue;
                }
                n_dot_l = -n_dot_l;
                origin = offset_point(p, geometric, l);
            }
            let mut light_colour = light.colour * incidence.factor;
            if light_colour == DVec3::ZERO {
                continue;
            }
            if !light.shadowless {
                let shadow_to = |target: DVec3, counts: &mut RayCounts| {
                    let to = target - origin;
                    let dist = to.length();
                    counts.shadow += 1;
                    self.shadow_filter(&Ray::new(origin, to / dist), dist * (1.0 - 1e-9))
                };
                let filter = match &light.area {
                    Some(area) => {
                        sampler.set_dimension(self.dimension(level, DIMS_PER_LIGHT * index as u32));
                        let s = sampler.get_2d();
                        if area.adaptive.is_some() && self.area_lights == AreaLightMode::Pov {
                            // POV-Ray's adaptive rule depends on what the corners see, so it
                            // is evaluated as POV-Ray does, with jitter drawn from this sample.
                            let seed = ((s.0 * 4_294_967_296.0) as u64) << 32
                                | (s.1 * 4_294_967_296.0) as u64;
                            area.adaptive_filter(
                                light.location,
                                light.location - p,
                                light_colour,
                                seed,
                                |t| shadow_to(t, counts),
                            )
                        } else {
                            // Several shadow samples: the stratified sample shifted by a
                            // well-spread set, so each is uniform and together they cover
                            // the light.
                            let n = self.light_samples.max(1);
                            let mut sum = DVec3::ZERO;
                            for k in 0..n {
                                let shift = (k as f64 / n as f64, (k as f64 * GOLDEN).fract());
                                let sk = ((s.0 + shift.0).fract(), (s.1 + shift.1).fract());
                                let target = area.sample_point(
                                    light.location,
                                    sk,
                                    light.location - p,
                                    self.area_lights,
                                    false,
                                );
                                sum += shadow_to(target, counts);
                            }
                            sum / n as f64
                        }
                    }
                    None => {
                        counts.shadow += 1;
                        self.shadow_filter(&Ray::new(origin, l), distance * (1.0 - 1e-9))
                    }
                };
                if filter == DVec3::ZERO {
                    continue;
                }
                light_colour *= filter;
            }
            let diffuse = diffuse_term(
                finish.diffuse,
                finish.brilliance,
                n_dot_l,
                att,
                finish.crand,
            );
            colour += c * light_colour * diffuse;
            if !light.shadowless {
                let highlight = phong_factor(finish.phong, finish.phong_size, n, d, l)
                    + specular_factor(finish.specular, finish.roughness, n, d, l);
                if highlight > 0.0 {
                    colour += light_colour * metallic_tint(finish.metallic, c, n_dot_l) * highlight;
                }
            }
        }
        colour
    }

    /// The fraction of light that reaches along a shadow ray: zero at an opaque object, and
    /// `C * filter + transmit` per crossing of a filtering one (no refraction), as POV-Ray.
    fn shadow_filter(&self, ray: &Ray, t_max: f64) -> DVec3 {
        let scene = self.scene;
        if !scene.any_transmitting {
            return if scene.world.occluded(ray, t_max) {
                DVec3::ZERO
            } else {
                DVec3::ONE
            };
        }
        let mut filter = DVec3::ONE;
        // Crossings of fading interiors, kept to measure the distance travelled inside.
        let mut fading = [(0.0f64, 0u32, false); MAX_FADING_CROSSINGS];
        let mut fading_len = 0;
        // Distances of the transparent crossings counted so far: POV-Ray follows a shadow ray
        // from crossing to crossing, so two faces at the same distance (a box and a cylinder
        // of one object meeting face to face) filter it once (measured: iortest's figures
        // match POV-Ray with a 0.01 gap or overlap but were darker where the faces touch).
        let mut counted = [0.0f64; MAX_FADING_CROSSINGS];
        let mut counted_len = 0;
        scene.world.shadow_hits(ray, t_max, |hit| {
            let primitive = scene.world.primitive_material(hit.primitive);
            let material = &scene.materials[primitive as usize];
            if !material.transmits {
                filter = DVec3::ZERO;
                return false;
            }
            let tie = 1e-9 * hit.t.abs().max(1.0);
            if counted[..counted_len]
                .iter()
                .any(|&t| (t - hit.t).abs() <= tie)
            {
                return true;
            }
            if counted_len < counted.len() {
                counted[counted_len] = hit.t;
                counted_len += 1;
            }
            let at = scene.world.texture_point(ray, hit);
            for layer in texture_layers(&material.texture, at).iter() {
                let c = layer.colour;
                filter *= c.rgb * c.filter + DVec3::splat(c.transmit);
            }
            if material.interior.fade_power > 0.0
                && material.interior.fade_distance > 0.0
                && fading_len < fading.len()
            {
                let leaving = scene.world.surface(ray, hit).normal.dot(ray.direction) > 0.0;
                fading[fading_len] = (hit.t, hit.primitive, leaving);
                fading_len += 1;
            }
            filter != DVec3::ZERO
        });
        if fading_len > 0 && filter != DVec3::ZERO {
            // POV-Ray fades shadow rays through an interior as it fades the rays that see
            // through it: over each stretch from entering to leaving the object.
            let crossings = &mut fading[..fading_len];
            crossings.sort_by(|a, b| a.0.total_cmp(&b.0));
            let speed = ray.direction.length();
            for i in 0..crossings.len() {
                let (t, primitive, leaving) = crossings[i];
                if !leaving {
                    continue;
                }
                let entry = crossings[..i]
                    .iter()
                    .rev()
                    .find(|c| c.1 == primitive && !c.2)
                    .map_or(0.0, |c| c.0);
                let material = &scene.materials[scene.world.primitive_material(primitive) as usize];
                filter *= fade(material, (t - entry) * speed);
            }
        }
        filter
    }
}

/// Fading interiors a shadow ray keeps track of; past this many, further ones do not fade.
const MAX_FADING_CROSSINGS: usize = 16;

/// Unpolarised Fresnel reflectance with relative index n and cos c of the incidence angle;
/// 1 under total internal reflection.
pub fn fresnel(c: f64, n: f64) -> f64 {
    let g2 = n * n + c * c - 1.0;
    if g2 <= 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c);
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
}

/// Heckbert's refraction: `eta = n_from / n_to`, `n` facing the incoming direction `d`;
/// `None` under total internal reflection.
pub fn refract(d: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    let c = -d.dot(n);
    let t = 1.0 + eta * eta * (c * c - 1.0);
    if t < 0.0 {
        return None;
    }
    Some((eta * d + (eta * c - t.sqrt()) * n).normalize())
}

/// Interior fade over `distance` inside an object.
/// The mirror direction of `d` in the shading normal `n` (facing the ray), kept outside the
/// true surface whose normal facing the ray is `outside`. A perturbed normal can send the
/// mirror ray into the surface. POV-Ray then mirrors it again in the true surface (measured:
/// the component along the geometric normal changes sign, the others keep theirs), unless
/// the ray also lies behind the perturbed normal (the normal was tilted past the ray): then
/// it reflects `d` in the true surface alone (measured: exactly the unperturbed direction).
fn mirror_direction(d: DVec3, n: DVec3, outside: DVec3) -> DVec3 {
    let mirror = d - 2.0 * d.dot(n) * n;
    let below = mirror.dot(outside);
    if below >= 0.0 {
        mirror
    } else if mirror.dot(n) < 0.0 {
        d - 2.0 * d.dot(outside) * outside
    } else {
        mirror - 2.0 * below * outside
    }
}

fn fade(material: &Material, distance: f64) -> DVec3 {
    let colour = material.interior.fade_colour;
    let ratio = distance / material.interior.fade_distance;
    if material.interior.fade_power >= 1000.0 {
        DVec3::new(
            (-(1.0 - colour.x) * ratio).exp(),
            (-(1.0 - colour.y) * ratio).exp(),
            (-(1.0 - colour.z) * ratio).exp(),
        )
    } else {
        colour + (DVec3::ONE - colour) / (1.0 + ratio.powf(material.interior.fade_power))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mirror_rays_stay_outside_the_true_surface() {
        let d = DVec3::new(0.0, -1.0, 1.0).normalize();
        let up = DVec3::Y;
        // Unperturbed: the plain mirror.
        let m = mirror_direction(d, up, up);
        assert!((m - DVec3::new(0.0, 1.0, 1.0).normalize()).length() < 1e-12);
        // Tilted sideways far enough to send the mirror below: only y changes sign.
        let n = DVec3::new(1.6, 1.0, 0.0).normalize();
        let raw = d - 2.0 * d.dot(n) * n;
        assert!(raw.y < 0.0 && raw.dot(n) > 0.0);
        let m = mirror_direction(d, n, up);
        assert!((m - DVec3::new(raw.x, -raw.y, raw.z)).length() < 1e-12);
        // Tilted past the ray (the ray meets the perturbed normal's back): the true mirror.
        let n = DVec3::new(0.0, 1.0, 2.0).normalize();
        assert!(d.dot(n) > 0.0);
        let m = mirror_direction(d, n, up);
        assert!((m - DVec3::new(0.0, 1.0, 1.0).normalize()).length() < 1e-12);
    }

    #[test]
    fn fresnel_conserves_and_saturates() {
        // Normal incidence into glass: ((n-1)/(n+1))^2 = 0.04 for n = 1.5.
        assert!((fresnel(1.0, 1.5) - 0.04).abs() < 1e-12);
        // Beyond the critical angle from inside glass: total reflection, no NaN.
        let critical = (1.0f64 - (1.0 / 1.5f64).powi(2)).sqrt();
        for c in [critical - 1e-9, critical * 0.5, 0.0] {
            let r = fresnel(c, 1.0 / 1.5);
            assert!(r.is_finite() && (r - 1.0).abs() < 1e-6, "{c}: {r}");
        }
        for c in [0.01, 0.3, 0.7, 0.99] {
            let r = fresnel(c, 1.33);
            assert!((0.0..=1.0).contains(&r));
        }
    }

    #[test]
    fn refraction_follows_snell() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        let n = DVec3::Y;
        let t = refract(d, n, 1.0 / 1.5).unwrap();
        // sin_t = sin_i / 1.5
        assert!((t.x - 0.6 / 1.5).abs() < 1e-12);
        assert!(refract(DVec3::new(0.9, -(1.0f64 - 0.81).sqrt(), 0.0), n, 1.5).is_none());
    }
}
