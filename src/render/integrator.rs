//! The integrator answers one question: what radiance comes back along a ray. It is
//! POV-Ray's recursive Whitted tracer (ambient, diffuse, highlights, shadow rays, mirror
//! reflection) with two stochastic changes that keep POV-Ray's expectation: area-light
//! visibility is estimated from one grid point drawn with POV-Ray's weights, and the
//! deterministic adc_bailout cut is replaced by Russian roulette, which keeps the
//! expectation of the max_trace_level-capped tree.

use glam::DVec3;

use crate::appearance::evaluate_pigment;
use crate::appearance::finish::{
    diffuse_factor, metallic_tint, phong_factor, reflectivity, specular_factor,
};
use crate::geometry::{Ray, flags, offset_point};
use crate::scene::LightKind;

use super::prepared::PreparedScene;
use super::sampler::PixelSampler;

/// Below this path weight, Russian roulette starts.
const ROULETTE_WEIGHT: f64 = 0.1;
/// The smallest survival probability, which bounds the variance roulette can add.
const ROULETTE_MIN_Q: f64 = 0.05;

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

pub struct Integrator<'a> {
    scene: &'a PreparedScene,
    /// Sampler dimensions used per trace level: two per light, one for roulette.
    dims_per_level: u32,
    pub roulette: bool,
}

/// Dimensions 0 and 1 are the pixel position.
const FIRST_PATH_DIMENSION: u32 = 2;

impl<'a> Integrator<'a> {
    pub fn new(scene: &'a PreparedScene) -> Integrator<'a> {
        Integrator {
            scene,
            dims_per_level: 2 * scene.lights.len() as u32 + 1,
            roulette: true,
        }
    }

    /// Radiance along a camera ray.
    pub fn radiance(&self, ray: &Ray, sampler: &mut PixelSampler, counts: &mut RayCounts) -> DVec3 {
        counts.camera += 1;
        self.trace(ray, 1, 1.0, flags::NO_IMAGE, sampler, counts)
    }

    /// `level` counts surfaces along the path, 1 for the camera ray: POV-Ray returns black
    /// for a ray whose level exceeds max_trace_level.
    fn trace(
        &self,
        ray: &Ray,
        level: u32,
        weight: f64,
        skip: u8,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let scene = self.scene;
        let Some(hit) = scene.world.intersect(ray, f64::INFINITY, skip) else {
            return scene.background.rgb;
        };
        let surface = scene.world.surface(ray, &hit);
        let material = &scene.materials[surface.material as usize];
        let texture = &material.texture;
        let finish = &texture.finish;
        let d = ray.direction.normalize();
        let p = surface.point;
        let geometric = surface.normal;
        // The shading normal, turned to face the incoming ray.
        let n = if geometric.dot(d) > 0.0 {
            -surface.shading_normal
        } else {
            surface.shading_normal
        };
        let pigment = evaluate_pigment(&texture.pigment, p);
        let c = pigment.rgb;
        let att = pigment.opacity(scene.legacy);

        let mut colour = c * finish.ambient * scene.settings.ambient_light * att;
        colour += c * finish.emission * att;

        let origin = offset_point(p, geometric, -d);
        let level_base = FIRST_PATH_DIMENSION + (level - 1) * self.dims_per_level;
        for (index, light) in scene.lights.iter().enumerate() {
            let (l, distance) = match light.kind {
                LightKind::Parallel { point_at } => {
                    let dir = (light.location - point_at).normalize_or(DVec3::Y);
                    // Shadows reach back to the plane through the light, across its direction.
                    let dist = (light.location - p).dot(dir);
                    (dir, dist)
                }
                _ => {
                    let to = light.location - p;
                    let dist = to.length();
                    (to / dist, dist)
                }
            };
            let mut n_dot_l = n.dot(l);
            if n_dot_l <= 0.0 {
                if !material.double_illuminate {
                    continue;
                }
                n_dot_l = -n_dot_l;
            }
            let mut light_colour = light.colour * light.attenuation(l, distance);
            if light_colour == DVec3::ZERO {
                continue;
            }
            if !light.shadowless {
                let visible = match &light.area {
                    Some(area) => {
                        sampler.set_dimension(level_base + 2 * index as u32);
                        let (s1, s2) = sampler.get_2d();
                        let target = area.sample_point(light.location, s1, s2, l);
                        let to = target - origin;
                        let dist = to.length();
                        counts.shadow += 1;
                        !scene
                            .world
                            .occluded(&Ray::new(origin, to / dist), dist * (1.0 - 1e-9))
                    }
                    None => {
                        counts.shadow += 1;
                        !scene
                            .world
                            .occluded(&Ray::new(origin, l), distance * (1.0 - 1e-9))
                    }
                };
                if !visible {
                    continue;
                }
            }
            let diffuse = diffuse_factor(finish.diffuse, finish.brilliance, n_dot_l);
            colour += c * light_colour * (diffuse * att);
            if !light.shadowless {
                let highlight = phong_factor(finish.phong, finish.phong_size, n, d, l)
                    + specular_factor(finish.specular, finish.roughness, n, d, l);
                if highlight > 0.0 {
                    light_colour *= metallic_tint(finish.metallic, c, n_dot_l);
                    colour += light_colour * highlight;
                }
            }
        }

        let reflection = &finish.reflection;
        if !reflection.is_zero() && level < scene.settings.max_trace_level {
            let r = reflectivity(
                reflection.min,
                reflection.max,
                reflection.falloff,
                -d.dot(n),
            );
            let path_weight = weight * r.max_element();
            if path_weight > 0.0 {
                // Roulette only where the reflected colour enters linearly; a reflection
                // exponent makes it a non-linear function, where a random cut would bias.
                let q =
                    if self.roulette && path_weight < ROULETTE_WEIGHT && reflection.exponent == 1.0
                    {
                        (path_weight / ROULETTE_WEIGHT).max(ROULETTE_MIN_Q)
                    } else {
                        1.0
                    };
                let survive = if q < 1.0 {
                    sampler.set_dimension(level_base + self.dims_per_level - 1);
                    sampler.get_1d() < q
                } else {
                    true
                };
                if survive {
                    let dir = d - 2.0 * d.dot(n) * n;
                    let reflected = Ray::new(offset_point(p, geometric, dir), dir);
                    counts.secondary += 1;
                    let incoming = self.trace(
                        &reflected,
                        level + 1,
                        path_weight / q,
                        flags::NO_REFLECTION,
                        sampler,
                        counts,
                    );
                    let incoming = if reflection.exponent == 1.0 {
                        incoming
                    } else {
                        incoming.max(DVec3::ZERO).powf(1.0 / reflection.exponent)
                    };
                    colour += r * incoming / q;
                }
            }
        }
        colour
    }
}
