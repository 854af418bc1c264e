//! Shooting one pass of photons, and gathering a pass at a shaded point (the method and
//! POV-Ray's conventions are in `crate::render::photons`).
//!
//! A photon leaves a light towards a `photons { target }` object, inside the cone (or, from
//! a parallel light, the beam) that the target's bounding sphere subtends; at each surface
//! it meets it goes on along the reflected or the refracted branch, chosen in proportion to
//! the branch's weight (the same weights camera rays use, so the photons see the same
//! glass), and after its first bounce it is stored wherever it lands.

use glam::DVec3;
use rand_pcg::Pcg32;

use crate::geometry::{Aabb, Ray, flags, offset_point};
use crate::render::fog::Segment;
use crate::render::lights::{AreaLightMode, PreparedLight};
use crate::render::photons::{Photon, PhotonBeam};
use crate::render::sampler::{mix, unit_f64};
use crate::scene::LightKind;

use super::interiors::InteriorStack;
use super::{Branches, Integrator, Path, Shading, Top, branches};

/// What photons go through unchanged: `photons { pass_through }`, and, as in POV-Ray,
/// objects that are `no_shadow` or `no_image` (measured: a glass sphere target with either
/// flag stores no photon and leaves the caustic of a second glass sphere below it exactly
/// as without it, 80,874 photons stored in both).
const PHOTON_SKIP: u8 = flags::PHOTON_PASS | flags::NO_SHADOW | flags::NO_IMAGE;

/// Keeps the photons' random streams apart from every other stream of the seed.
const PHOTON_SALT: u64 = 0x5048_4f54_4f4e_0001;

/// One pass's photons: where they landed on surfaces, and their beams through media that
/// scatter.
#[derive(Debug, Default)]
pub struct Shot {
    pub surface: Vec<Photon>,
    pub volume: Vec<PhotonBeam>,
}

/// Where a photon is on its path: how far it has come, the light it carries (before its
/// spread over that length), and whether it has turned yet.
struct Travel {
    length: f64,
    power: DVec3,
    /// Reflected, or refracted through a change of index. Until then the photon is on
    /// the light's own way, where shadow rays already bring its light (through clear and
    /// filtering surfaces alike), so it lights nothing. POV-Ray lights with such photons in
    /// place of the direct light instead: the same light in expectation, blurred by its
    /// gather (a spotlight through a clear target box of media: the image's mean 0.14246
    /// without photons and 0.13696 with 240,148 media photons stored; penumbra, lighting
    /// with them and the direct light both, gave 0.32597).
    turned: bool,
}

/// What the light a photon carries becomes after `length` of path: point and spot lights
/// spread it over the square of the length, as POV-Ray's lights do not fall off (see
/// `crate::render::photons`), times the light's own fade.
pub(super) fn spread(light: &PreparedLight, length: f64) -> f64 {
    let area = match light.kind {
        LightKind::Point | LightKind::Spot { .. } => length * length,
        LightKind::Parallel { .. } | LightKind::Cylinder { .. } => 1.0,
    };
    area * light.fade(length)
}

/// Where one (light, target) pair's photons start and how much light each carries.
#[derive(Clone, Copy)]
struct Beam {
    /// The cone's apex (point and spot lights) or the beam's centre (parallel lights).
    origin: DVec3,
    axis: DVec3,
    /// Point lights: the cosine of the cone's half angle; parallel: unused.
    cos_max: f64,
    /// Parallel lights: the beam's radius.
    radius: f64,
    /// Point and spot lights spread their light over distance; POV-Ray's lights do not
    /// fall off, so such a photon's power grows with the square of its path.
    spreads: bool,
}

impl Beam {
    fn new(light: &PreparedLight, target: &Aabb) -> Option<Beam> {
        Beam::from(light, light.location, target)
    }

    /// The beam as if the light stood at `origin` (one point of an area light).
    fn from(light: &PreparedLight, origin: DVec3, target: &Aabb) -> Option<Beam> {
        let centre = (target.min + target.max) * 0.5;
        let r = (target.max - target.min).length() * 0.5;
        match light.kind {
            LightKind::Point | LightKind::Spot { .. } => {
                let to = centre - origin;
                let d = to.length();
                if d.is_nan() || d <= 0.0 {
                    return None;
                }
                let cos_max = if d <= r {
                    -1.0
                } else {
                    (1.0 - (r / d).powi(2)).sqrt()
                };
                Some(Beam {
                    origin,
                    axis: to / d,
                    cos_max,
                    radius: 0.0,
                    spreads: true,
                })
            }
            LightKind::Parallel { point_at } | LightKind::Cylinder { point_at, .. } => {
                let axis = (point_at - light.location).normalize_or(-DVec3::Y);
                // From the plane through the light, across its direction.
                let back = (light.location - centre).dot(axis);
                Some(Beam {
                    origin: centre + axis * back,
                    axis,
                    cos_max: 1.0,
                    radius: r,
                    spreads: false,
                })
            }
        }
    }

    /// The k-th of n photons: its ray, and the light it carries per unit of the density
    /// of photons in its direction (see `density`; before its path's length).
    fn photon(&self, light: &PreparedLight, (k, n): (u32, u32), rng: &mut Pcg32) -> (Ray, DVec3) {
        // Stratified over the cone's (or disc's) first coordinate, uniform over the turn.
        let u = (f64::from(k) + unit_f64(rng)) / f64::from(n);
        let phi = std::f64::consts::TAU * unit_f64(rng);
        let (a, b) = self.axis.any_orthonormal_pair();
        let across = a * phi.cos() + b * phi.sin();
        if self.spreads {
            let cos = 1.0 - u * (1.0 - self.cos_max);
            let sin = (1.0 - cos * cos).max(0.0).sqrt();
            let dir = self.axis * cos + across * sin;
            let cone = light
                .incidence_from(self.origin + dir, self.origin)
                .map_or(0.0, |i| i.factor / light.fade(1.0));
            (Ray::new(self.origin, dir), light.colour * cone)
        } else {
            let start = self.origin + across * (self.radius * u.sqrt());
            let beam = light
                .incidence(start + self.axis)
                .map_or(0.0, |i| i.factor / light.fade(1.0));
            (Ray::new(start, self.axis), light.colour * beam)
        }
    }

    /// The beam's solid angle (cones) or area (discs).
    fn measure(&self) -> f64 {
        if self.spreads {
            std::f64::consts::TAU * (1.0 - self.cos_max)
        } else {
            std::f64::consts::PI * self.radius * self.radius
        }
    }

    /// How densely `n` photons of this beam fall about a photon's ray: per steradian of
    /// its cone, or per unit area of its disc; 0 when the ray lies outside the beam.
    fn density(&self, ray: &Ray, n: u32) -> f64 {
        let inside = if self.spreads {
            ray.direction.normalize().dot(self.axis) >= self.cos_max
        } else {
            let off = ray.origin - self.origin;
            (off - self.axis * off.dot(self.axis)).length() <= self.radius
        };
        if inside {
            f64::from(n) / self.measure()
        } else {
            0.0
        }
    }
}

/// With `photons { area_light }` a point or spot area light's photons start uniformly
/// over its area (its disc if circular), each with the cone towards the target from where
/// it starts, so the caustic averages the light's points as its direct light does with
/// area_illumination; otherwise (POV-Ray's default) they start at its centre.
fn area_origin(light: &PreparedLight, target: &Aabb, rng: &mut Pcg32) -> Option<DVec3> {
    let area = light.area.as_ref().filter(|_| light.photons.area_light)?;
    if !matches!(light.kind, LightKind::Point | LightKind::Spot { .. }) {
        return None;
    }
    // `orient` turns the light to face the target, as it faces a shaded point.
    let towards = light.location - (target.min + target.max) * 0.5;
    let frame = area.frame(light.location, towards);
    let s = (unit_f64(rng), unit_f64(rng));
    Some(area.sample_point(&frame, s, AreaLightMode::Continuous))
}

/// Every target's beam as if the light stood at `origin`, written into `beams`.
fn beams_from(
    light: &PreparedLight,
    origin: DVec3,
    targets: &[Aabb],
    beams: &mut Vec<Option<Beam>>,
) {
    beams.clear();
    beams.extend(targets.iter().map(|t| Beam::from(light, origin, t)));
}

/// The density of photons about a ray of beam `own`, summed over every beam that holds it.
/// Targets' beams overlap (a ring round a ball: the ring's cone holds the ball's), and a
/// photon carries its light over this sum (the balance heuristic), so that light reaching a
/// target through several beams is counted once, not once per beam.
fn overlap_density(beams: &[Option<Beam>], own: usize, ray: &Ray, n: u32) -> f64 {
    let others: f64 = (beams.iter().enumerate())
        .filter(|&(i, _)| i != own)
        .filter_map(|(_, b)| b.as_ref().map(|b| b.density(ray, n)))
        .sum();
    // The photon lies in its own beam by construction, whatever rounding says at the edge.
    let own_beam = beams[own].expect("the photon's own beam");
    f64::from(n) / own_beam.measure() + others
}

impl Integrator<'_> {
    /// One pass's photons, about `count` shot in all, shared equally among the (light,
    /// target) pairs; a pure function of (seed, pass). With `photons { media }` the photons'
    /// paths through media that scatter are kept too, and the media dim them.
    pub fn shoot_photons(&self, pass: u32, seed: u64, count: u32) -> Shot {
        let targets = self.scene.world.photon_targets();
        let lights: Vec<usize> = (0..self.scene.lights.len())
            .filter(|&i| {
                let p = self.scene.lights[i].photons;
                !(p.reflection == Some(false) && p.refraction == Some(false))
            })
            .collect();
        let pairs = (lights.len() * targets.len()) as u32;
        let mut out = Shot::default();
        if pairs == 0 {
            return out;
        }
        let n = (count / pairs).max(1);
        for &l in &lights {
            let light = &self.scene.lights[l];
            let beams: Vec<Option<Beam>> = targets.iter().map(|t| Beam::new(light, t)).collect();
            // An area light's photons each start at their own point: the beams from there.
            let mut moved = Vec::with_capacity(targets.len());
            for t in 0..targets.len() {
                let Some(own) = beams[t] else {
                    continue;
                };
                // Photons start inside whatever holds their light, as camera rays start
                // inside what holds the camera (glassthing's glass stands in a closed room):
                // found once per beam, or per photon where each starts at its own point.
                let own_start = super::interiors_at(self.scene, own.origin);
                let key = mix(seed ^ PHOTON_SALT ^ (u64::from(pass) << 32) ^ ((l as u64) << 16))
                    ^ mix(t as u64);
                let mut rng = Pcg32::new(key, mix(key) | 1);
                for k in 0..n {
                    let (from, start) = match area_origin(light, &targets[t], &mut rng) {
                        Some(origin) => {
                            beams_from(light, origin, targets, &mut moved);
                            (&moved, super::interiors_at(self.scene, origin))
                        }
                        None => (&beams, own_start),
                    };
                    let Some(beam) = from[t] else {
                        continue;
                    };
                    let (ray, light_in) = beam.photon(light, (k, n), &mut rng);
                    let power = light_in / overlap_density(from, t, &ray, n);
                    if power != DVec3::ZERO {
                        let from_light = (light, l as u32, start);
                        self.trace_photon(ray, power, from_light, &mut rng, &mut out);
                    }
                }
            }
        }
        out
    }

    /// Follows one photon from its light, storing it where it lands once it has turned
    /// ([`Travel::turned`]), and (with `photons { media }`) its path through media that
    /// scatter.
    fn trace_photon(
        &self,
        mut ray: Ray,
        power: DVec3,
        (light, light_index, start): (&PreparedLight, u32, InteriorStack),
        rng: &mut Pcg32,
        out: &mut Shot,
    ) {
        let settings = self.scene.settings.photons.unwrap_or_default();
        let max_level = settings
            .max_trace_level
            .unwrap_or(self.scene.settings.max_trace_level);
        let in_media = settings.media.is_some();
        // In media a `pass_through` object is met rather than skipped, so that the photon
        // knows when it enters or leaves the media such an object usually holds.
        let skip = if in_media {
            PHOTON_SKIP & !flags::PHOTON_PASS
        } else {
            PHOTON_SKIP
        };
        let mut path = Path {
            level: 1,
            weight: 1.0,
            skip,
            interiors: start,
            wavelength: None,
            bounces: 0,
        };
        let mut travel = Travel {
            length: 0.0,
            power,
            turned: false,
        };
        while let Some(hit) = self.scene.world.intersect(&ray, f64::INFINITY, path.skip) {
            let step = hit.t * ray.direction.length();
            if in_media {
                let segment = Segment {
                    origin: ray.origin,
                    direction: ray.direction.normalize(),
                    length: step,
                };
                let from = (light, light_index, &path);
                self.through_media(&segment, from, &mut travel, &mut out.volume);
            }
            travel.length += step;
            let at = path;
            let surface = self.scene.world.surface(&ray, &hit);
            let s = self.shading(&ray, &hit, &surface, &at);
            if s.material.photons.pass_through {
                path.interiors = super::crossing(&s).2;
                ray = Ray::new(offset_point(s.surface.point, s.surface.normal, s.d), s.d);
                continue;
            }
            // Shot at a target, a photon that meets something else first is lost (measured:
            // a clear slab between the light and a glass target, none stored, whatever
            // the light's and the slab's photons blocks).
            if path.level == 1 && !s.material.photons.target {
                return;
            }
            if travel.turned && !s.material.photons.no_collect {
                let carried = travel.power * spread(light, travel.length);
                out.surface.push(Photon::new(s.surface.point, carried, s.d));
            }
            if path.level >= max_level || travel.power == DVec3::ZERO {
                return;
            }
            let Some((dir, weight, interiors)) = self.photon_bounce(&s, light, rng) else {
                return;
            };
            travel.power *= weight;
            // A straight crossing goes on along `s.d` exactly.
            travel.turned |= dir != s.d;
            path.interiors = interiors;
            // Every surface met counts, a straight crossing too (measured: photons through
            // four clear slabs under a glass target stored once more per level added, up
            // to both faces of every slab and the floor).
            path.level += 1;
            ray = Ray::new(offset_point(s.surface.point, s.surface.normal, dir), dir);
        }
    }

    /// A photon's way along one straight segment of its path: where an interior's media
    /// scatter (once it has turned, from a light that lights media) the segment is kept
    /// as a beam carrying the photon's light as it starts, and the media dim the photon
    /// over the whole segment for what lies beyond it, as POV-Ray does ([`PhotonBeam`]).
    fn through_media(
        &self,
        segment: &Segment,
        (light, light_index, path): (&PreparedLight, u32, &Path),
        travel: &mut Travel,
        beams: &mut Vec<PhotonBeam>,
    ) {
        let dimming = (&path.interiors, light.media_attenuation);
        let (t, scatters) = self.photon_segment(segment, dimming);
        let step = segment.length;
        if scatters && travel.turned && light.lights_media && step > 0.0 {
            beams.push(PhotonBeam {
                origin: segment.origin.as_vec3().to_array(),
                direction: segment.direction.as_vec3().to_array(),
                length: step as f32,
                power: travel.power.as_vec3().to_array(),
                travelled: travel.length as f32,
                light: light_index,
            });
        }
        travel.power *= t;
    }

    /// The branch a photon takes at a surface: its direction, the factor on its power
    /// (the branch's weight over the chance it was chosen) and the interiors it is in after.
    fn photon_bounce(
        &self,
        s: &Shading,
        light: &PreparedLight,
        rng: &mut Pcg32,
    ) -> Option<(DVec3, DVec3, InteriorStack)> {
        let top = self.top_layer(s)?;
        let b: Branches = branches(s, &top);
        let object = s.material.photons;
        let reflect = if object.reflects(&light.photons) {
            b.reflect
        } else {
            DVec3::ZERO
        };
        let transmit = if object.refracts(&light.photons) {
            b.transmit
        } else {
            DVec3::ZERO
        };
        let (wr, wt) = (reflect.abs().max_element(), transmit.abs().max_element());
        if wr + wt <= 0.0 {
            return None;
        }
        let pr = wr / (wr + wt);
        if unit_f64(rng) < pr {
            return Some((b.mirror, reflect / pr, s.path.interiors));
        }
        let chosen = 1.0 - pr;
        Some(match b.refracted {
            Some(_) if b.straight => (s.d, transmit / chosen, b.beyond),
            Some(dir) => (dir, transmit / chosen, b.beyond),
            None => (b.mirror, transmit / chosen, s.path.interiors),
        })
    }

    /// What this sample's photon pass brings to the shaded point (irradiance) on the
    /// viewer's side, or from `behind`.
    pub(super) fn caustic(&self, s: &Shading, index: u32, brilliance: f64, behind: bool) -> DVec3 {
        let Some(maps) = self.photons.and_then(|m| m.pass(index)) else {
            return DVec3::ZERO;
        };
        let facing = if behind { -s.facing } else { s.facing };
        maps.surface.irradiance(s.surface.point, facing, brilliance)
    }

    /// The top layer's pigment and finish and what the layers let through, as `shade`
    /// finds them.
    fn top_layer<'s>(&'s self, s: &Shading<'s>) -> Option<Top<'s>> {
        let layers = self.layers(s);
        let mut through = DVec3::ONE;
        let mut top = None;
        for layer in layers {
            let c = layer.colour;
            top.get_or_insert((c, layer.finish));
            through *= c.rgb * c.filter + DVec3::splat(c.transmit);
            if through == DVec3::ZERO {
                break;
            }
        }
        let (pigment, finish) = top?;
        Some(Top {
            pigment,
            finish,
            through,
        })
    }
}
