//! What participating media do to a ray segment: the light they take out of what lies
//! behind, and the light they emit and scatter towards the viewer.
//!
//! POV-Ray sums a fixed quadrature per interval; penumbra estimates the same integral
//! without bias. Along a segment of length L it takes n points at L (k + u) / n, k < n, for
//! one stratified u per sample (a systematic sample: each point uniform, together spread
//! evenly), and at each the source (emission, and the light each lamp brings, times the
//! phase function) weighted by the transmittance from the segment's start. Where the
//! media are the same everywhere the transmittance is exp(-sigma s) exactly; elsewhere it
//! is ratio tracking (Novak et al. 2014): steps at the rate of a bound of the extinction,
//! each multiplying by 1 - sigma(x) / bound, whose expectation is exp(-integral of sigma)
//! for any bound.
//!
//! Where media apply, measured on povray 3.7: only where the ray is inside no solid
//! (non-`hollow`) object, as with fog (a hollow box of emitting media inside a solid
//! sphere, or a solid box of media, shows nothing); there the atmospheric media and those
//! of every interior the ray is in add up (two overlapping boxes emitting 0.3 and 0.1,
//! overlapping by half their depth: 0.40). Shadow rays are dimmed by the media of the
//! interiors they cross always, and by atmospheric media and fog only from lights with
//! `media_attenuation on` (a slab lit through an absorbing box: exp(-1) with or without).

use glam::DVec3;
use rand_pcg::Pcg32;

use super::direct::ShadowQuery;
use super::interiors::InteriorStack;
use super::{Integrator, RayCounts};
use crate::render::dimensions::Purpose;
use crate::render::fog::{FogEffect, Segment};
use crate::render::media::{MediaTable, phase};
use crate::render::photons::PhotonBeam;
use crate::render::sampler::PixelSampler;

/// Media one segment can be in at once; further ones are left out.
const MAX_ACTIVE: usize = 16;

/// Below this transmittance, ratio tracking plays Russian roulette to stop.
const TRACKING_ROULETTE: f64 = 0.01;

/// The media that apply along one stretch of a ray, as indices into the media table.
#[derive(Clone, Copy)]
pub(super) struct Active {
    ids: [u32; MAX_ACTIVE],
    len: usize,
}

impl Active {
    /// The media of the interiors in `stack`, and the atmosphere's if `atmospheric`.
    pub(super) fn new(table: &MediaTable, stack: &InteriorStack, atmospheric: bool) -> Active {
        let mut a = Active {
            ids: [0; MAX_ACTIVE],
            len: 0,
        };
        if !stack.in_atmosphere() {
            return a;
        }
        let outer = atmospheric.then(|| table.atmospheric()).into_iter();
        let inner = stack.ids().iter().map(|&id| table.interior(id));
        for id in outer.chain(inner).flatten() {
            if a.len < MAX_ACTIVE {
                a.ids[a.len] = id;
                a.len += 1;
            }
        }
        a
    }

    fn ids(&self) -> &[u32] {
        &self.ids[..self.len]
    }

    pub(super) fn is_empty(&self) -> bool {
        self.len == 0
    }
}

/// Uniform values for ratio tracking.
pub(super) trait Uniform {
    fn next(&mut self) -> f64;
}

impl Uniform for crate::render::sampler::FreeStream {
    fn next(&mut self) -> f64 {
        self.next_f64()
    }
}

impl Uniform for Pcg32 {
    fn next(&mut self) -> f64 {
        use rand::Rng;
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// The transmittance from a ray's start to growing distances along it.
struct Tracker<'m> {
    table: &'m MediaTable,
    active: Active,
    origin: DVec3,
    direction: DVec3,
    /// The extinction where it is the same everywhere.
    uniform: Option<DVec3>,
    bound: f64,
    /// Where the next tracking event is, and the transmittance before it.
    next: f64,
    t: DVec3,
}

impl<'m> Tracker<'m> {
    fn new(table: &'m MediaTable, active: Active, segment: &Segment, u: &mut dyn Uniform) -> Self {
        let media = || active.ids().iter().map(|&i| &table.media[i as usize]);
        let uniform = media().all(|m| m.homogeneous()).then(|| {
            media()
                .map(|m| m.coefficients(m.density(segment.origin)).extinction)
                .sum()
        });
        let bound: f64 = media().map(|m| m.extinction_bound()).sum();
        let mut tracker = Tracker {
            table,
            active,
            origin: segment.origin,
            direction: segment.direction,
            uniform,
            bound,
            next: 0.0,
            t: DVec3::ONE,
        };
        tracker.step(u);
        tracker
    }

    fn step(&mut self, u: &mut dyn Uniform) {
        self.next += if self.bound > 0.0 {
            -(1.0 - u.next()).ln() / self.bound
        } else {
            f64::INFINITY
        };
    }

    /// The transmittance from the start to `s` (non-decreasing calls).
    fn to(&mut self, s: f64, u: &mut dyn Uniform) -> DVec3 {
        if let Some(sigma) = self.uniform {
            return (-sigma * s).exp();
        }
        while self.next <= s && self.t != DVec3::ZERO {
            let p = self.origin + self.direction * self.next;
            let sigma: DVec3 = self
                .active
                .ids()
                .iter()
                .map(|&i| {
                    let m = &self.table.media[i as usize];
                    m.coefficients(m.density(p)).extinction
                })
                .sum();
            self.t *= DVec3::ONE - sigma / self.bound;
            if self.t.abs().max_element() < TRACKING_ROULETTE {
                self.t = if u.next() < 0.5 {
                    DVec3::ZERO
                } else {
                    self.t * 2.0
                };
            }
            self.step(u);
        }
        self.t
    }
}

/// One point on a ray segment in media, where their source is estimated.
struct MediaPoint<'a> {
    p: DVec3,
    /// The ray's unit direction.
    d: DVec3,
    active: &'a Active,
    interiors: &'a InteriorStack,
    level: u32,
}

impl Integrator<'_> {
    /// What the media do to the light behind `segment`, a ray at trace `level` inside
    /// `interiors`.
    pub(super) fn media_effect(
        &self,
        segment: &Segment,
        interiors: &InteriorStack,
        level: u32,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> FogEffect {
        let mut effect = FogEffect {
            factor: DVec3::ONE,
            added: DVec3::ZERO,
        };
        let table = &self.scene.media;
        let active = Active::new(table, interiors, true);
        if active.is_empty() {
            return effect;
        }
        if !segment.length.is_finite() {
            // POV-Ray returns infinity for emission and scattering along a ray that leaves
            // the scene; penumbra keeps the light out and adds nothing (docs/differences.md).
            let media = active.ids().iter().map(|&i| &table.media[i as usize]);
            let blocked = media.clone().any(|m| m.extinction_bound() > 0.0);
            effect.factor = if blocked { DVec3::ZERO } else { DVec3::ONE };
            return effect;
        }
        let dim = self.layout.dimension(level, Purpose::MediaDistance);
        sampler.set_dimension(dim);
        let u = sampler.get_1d();
        let mut stream = sampler.free_stream(dim);
        let mut tracker = Tracker::new(table, active, segment, &mut stream);
        let n = active
            .ids()
            .iter()
            .map(|&i| table.media[i as usize].points)
            .max()
            .unwrap_or(1);
        let step = segment.length / n as f64;
        for k in 0..n {
            let s = step * (k as f64 + u);
            let t = tracker.to(s, &mut stream);
            if t == DVec3::ZERO {
                break;
            }
            let at = MediaPoint {
                p: segment.origin + segment.direction * s,
                d: segment.direction,
                active: &active,
                interiors,
                level,
            };
            let source = self.media_source(&at, sampler, counts);
            effect.added += t * source * step;
        }
        effect.factor = tracker.to(segment.length, &mut stream);
        effect
    }

    /// The light the media at a point send back along the ray per unit length: their
    /// emission, and what they scatter of each light that lights media.
    fn media_source(
        &self,
        at: &MediaPoint,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let table = &self.scene.media;
        let (p, d, active) = (at.p, at.d, at.active);
        let mut density = [DVec3::ZERO; MAX_ACTIVE];
        let mut source = DVec3::ZERO;
        let mut scatters = false;
        for (k, &i) in active.ids().iter().enumerate() {
            let m = &table.media[i as usize];
            density[k] = m.density(p);
            source += m.coefficients(density[k]).emission;
            scatters |= m.scatters() && density[k] != DVec3::ZERO;
        }
        if !scatters {
            return source;
        }
        source += self.media_photons(at, &density, sampler.index());
        for (index, light) in self.scene.lights.iter().enumerate() {
            if !light.lights_media {
                continue;
            }
            let Some(incidence) = light.incidence(p) else {
                continue;
            };
            let colour = light.colour * incidence.factor;
            if colour == DVec3::ZERO {
                continue;
            }
            let query = ShadowQuery {
                light,
                index: index as u32,
                level: at.level,
                p,
                origin: p,
                inside: at.interiors,
                colour,
            };
            let arriving =
                colour * self.visibility(&query, incidence.l, incidence.distance, sampler, counts);
            if arriving == DVec3::ZERO {
                continue;
            }
            let c = incidence.l.dot(d);
            for (k, &i) in active.ids().iter().enumerate() {
                let m = &table.media[i as usize];
                source += arriving * m.scattering * density[k] * phase(m.phase, c);
            }
        }
        source
    }

    /// The light of this sample's photon beams that the media at a point scatter along
    /// the ray (`photons { media }`): the caustics' light in the media, which no light's
    /// shadow ray finds.
    fn media_photons(&self, at: &MediaPoint, density: &[DVec3], index: u32) -> DVec3 {
        let Some(map) = self.photons.and_then(|m| m.pass(index)).map(|m| &m.volume) else {
            return DVec3::ZERO;
        };
        if map.is_empty() {
            return DVec3::ZERO;
        }
        let table = &self.scene.media;
        let atmosphere = table.atmospheric();
        let carried = |beam: &PhotonBeam, s: f64| {
            let light = &self.scene.lights[beam.light as usize];
            let travelled = f64::from(beam.travelled) + s;
            beam.power() * super::photons::spread(light, travelled)
        };
        map.in_scattered(at.p, at.d, carried, |c| {
            (at.active.ids().iter().zip(density))
                .filter(|&(i, _)| !atmosphere.contains(i))
                .map(|(&i, &rho)| {
                    let m = &table.media[i as usize];
                    m.scattering * rho * phase(m.phase, c)
                })
                .sum()
        })
    }

    /// What the media do to a photon along one segment of its path: the transmittance
    /// over it (the media dim it as they dim a shadow ray from its light: atmospheric
    /// media only with `media_attenuation`), and whether an interior's media that scatter
    /// apply there (POV-Ray stores no photons in atmospheric media: none stored of
    /// 1,671,862 shot through a scattering atmosphere, 841,983 on the surfaces beyond).
    pub(super) fn photon_segment(
        &self,
        segment: &Segment,
        (interiors, attenuated_by_atmosphere): (&InteriorStack, bool),
    ) -> (DVec3, bool) {
        let table = &self.scene.media;
        let scattering = Active::new(table, interiors, false);
        let scatters = (scattering.ids().iter()).any(|&i| table.media[i as usize].scatters());
        let t = self.media_transmittance(segment, interiors, attenuated_by_atmosphere);
        (t, scatters)
    }

    /// What the media leave of the light along one stretch of a shadow ray inside
    /// `interiors`: the interiors' media, and the atmosphere's too if `atmospheric`.
    pub(super) fn media_transmittance(
        &self,
        segment: &Segment,
        interiors: &InteriorStack,
        atmospheric: bool,
    ) -> DVec3 {
        let table = &self.scene.media;
        let active = Active::new(table, interiors, atmospheric);
        if active.is_empty() || segment.length <= 0.0 {
            return DVec3::ONE;
        }
        // Shadow rays draw their tracking steps from a stream seeded by the stretch itself:
        // a pure function of the geometry, independent of the camera sample's streams.
        let key = segment
            .origin
            .to_array()
            .into_iter()
            .chain(segment.direction.to_array());
        let seed = key.fold(0x6d65_6469_6173_6864u64, |h, x| {
            (h ^ x.to_bits())
                .wrapping_mul(0x9e37_79b9_7f4a_7c15)
                .rotate_left(29)
        });
        let mut rng = Pcg32::new(seed, 0x0a02_bdbf_7bb3_c0a7);
        let mut tracker = Tracker::new(table, active, segment, &mut rng);
        tracker.to(segment.length, &mut rng)
    }
}
