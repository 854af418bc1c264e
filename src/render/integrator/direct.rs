//! Light arriving straight from the light sources: ambient and emission, and for each light
//! the diffuse term and the highlights, through shadow rays that filter through transparent
//! objects as POV-Ray's do.

use std::cell::Cell;

use glam::DVec3;

use crate::appearance::finish::{
    diffuse_term, irid_factor, metallic_tint, phong_factor, specular_factor,
};
use crate::appearance::{perturbed_normal, texture_layers};
use crate::geometry::{Hit, NO_ITEM, Occluders, Ray, Shaft, offset_point};
use crate::render::dimensions::Purpose;
use crate::render::lights::LightSamples;
use crate::render::lights::{AreaLightMode, GOLDEN, PreparedArea, PreparedLight, WeightOrder};
use crate::render::prepared::{Material, PreparedScene};
use crate::render::sampler::{PixelSampler, permute};
use crate::scene::{Colour, Finish, LightGroup};

/// The largest area_illumination grid a one-ray pixel shades whole. Measured, adaptive,
/// squared error times time against shading a few points spread over the grid: 7 x 3
/// (scenes/area_illumination.pov, 640x480, against POV-Ray) 6-11% lower at 4, 8 and 16
/// spp; 9 x 9 (the same scene, 320x240, against a 256-spp render) 8% and 22% lower at 4
/// and 16 spp. Larger grids cost in proportion and were not measured.
const WHOLE_GRID_POINTS: u32 = 81;

/// From this average of samples per pixel on, every sample shades a small area_illumination
/// grid whole, not only one-ray pixels' (the pilot's kept samples and penumbrae's too).
/// Measured, scenes/area_illumination.pov (7 x 3, jittered) at 640x480 adaptive, 2 seeds,
/// squared error times time whole against spread at 1 / 1.125 / 1.25 / 1.5 / 2 / 3 / 4 / 6
/// / 8 / 16 spp: 3 / 10 / 21 / 39 / 34 / 23 / 18 / 5 / 12 / -2% lower (at 32, 12% higher:
/// there the reference's own noise, about 0.001, is most of the RMSE, and time decides).
/// But below 1.25 spp, where a render is one cheap sample per pixel, whole grids made it
/// 1.5x dearer (0.45 -> 0.67 s) for an error it did not need: POV-Ray's `-A` error
/// (0.0079) came at 0.67 s instead of 0.46 s.
pub(super) const WHOLE_GRID_FROM_SPP: f64 = 1.25;

use super::interiors::InteriorStack;
use super::optics::{caustic_factor, fade};
use super::{Integrator, RayCounts, Shading};
use crate::render::fog::{Segment, light_through_fog};

/// Crossings a shadow ray keeps track of; past this many, further ones neither fade nor
/// are told apart from crossings at the same distance.
const MAX_CROSSINGS: usize = 32;

/// Lights whose shadow a shading point keeps for its texture's later layers.
const MEMO_LIGHTS: usize = 4;

/// Shadow rays from one point towards an area light from which the point culls the scene
/// to a shaft first ([`crate::geometry::Shaft`]). A shaft costs about 1,000 instructions,
/// three or four shadow rays of a small scene; it spares every ray where nothing meets it,
/// but near a penumbra, where adaptive sampling's grid points are, only the walk of the
/// tree. Measured (callgrind, 320x240, 2 spp adaptive, instructions against no shafts)
/// from 4 / 8 / 16 rays: soft_shadow -1.0 / -2.8 / -2.0%, area_grid_6x2 +1.4 / -0.1 /
/// +0.1%, area_circular_9x9 -3.2 / -6.3 / -5.9%, area_illumination -2.1 / -3.3 / -2.5%
/// (from 2: +5.7% on soft_shadow); uniform, soft_shadow -24% from 8 and -2% from 16.
const SHAFT_FROM_RAYS: f64 = 8.0;

/// How a shadow ray finds what stops it.
#[derive(Clone, Copy)]
enum Occlusion<'a> {
    /// A walk of the tree.
    Walk,
    /// The item that stopped the last stopped ray first, then a walk.
    Hinted(&'a Cell<u32>),
    /// The items of the shaft the ray lies in.
    Among(&'a Occluders),
}

/// The shadow filters found at one shading point, per light and side of the surface: the
/// same for every texture layer (the shadow query depends on the light, the point and the
/// side, and an area light's jitter on the sample, none of them on the layer), so a layered
/// texture traces a light's shadow rays once, as POV-Ray does, not once per layer. Measured:
/// incdemo/woods/wood_18.pov (two layers) traced 116,852 shadow rays at 320x240, one
/// sample, where POV-Ray tests 58,481.
#[derive(Default)]
pub(super) struct ShadowMemo {
    /// Bit 2 * light + side: that filter is known.
    known: u8,
    filters: [DVec3; 2 * MEMO_LIGHTS],
}

impl ShadowMemo {
    /// The filter of light `index` on `side` (1: the side the normal does not face), from
    /// the memo or from `find`, which it then keeps.
    fn filter(&mut self, index: usize, flipped: bool, find: impl FnOnce() -> DVec3) -> DVec3 {
        if index >= MEMO_LIGHTS {
            return find();
        }
        let slot = 2 * index + usize::from(flipped);
        if self.known >> slot & 1 == 0 {
            self.filters[slot] = find();
            self.known |= 1 << slot;
        }
        self.filters[slot]
    }
}

/// One texture layer as the lights see it.
#[derive(Clone, Copy, Debug)]
pub(super) struct ShadedLayer<'f> {
    pub pigment: Colour,
    pub finish: &'f Finish,
    /// The layer's opacity, which scales its ambient, emission and diffuse terms.
    pub att: f64,
}

impl ShadedLayer<'_> {
    /// Ambient (scaled by the scene's ambient_light) and emission.
    pub(super) fn ambient_and_emission(&self, ambient_light: DVec3) -> DVec3 {
        let c = self.pigment.rgb;
        let mut colour = c * self.finish.ambient * ambient_light * self.att;
        colour += c * self.finish.emission * self.att;
        colour
    }

    /// What the layer reflects of the light radiosity gathers: pigment, the diffuse value
    /// as written, opacity.
    pub(super) fn radiosity_albedo(&self) -> DVec3 {
        self.pigment.rgb * self.finish.radiosity_diffuse * self.att
    }

    /// The same behind the surface, through `diffuse`'s second value.
    pub(super) fn radiosity_albedo_back(&self) -> DVec3 {
        self.pigment.rgb * self.finish.diffuse_back * self.att
    }

    /// The light photons bring (irradiance `e`), shown as POV-Ray shows it: times the
    /// diffuse colour, as a light shining straight at the surface would be; photons that
    /// arrive from `behind` through `diffuse`'s second value.
    pub(super) fn caustic(&self, e: DVec3, behind: bool) -> DVec3 {
        self.pigment.rgb * e * (self.diffuse_value(behind) * self.att)
    }

    /// `diffuse`'s first value, or its second for light arriving from behind.
    fn diffuse_value(&self, behind: bool) -> f64 {
        if behind {
            self.finish.diffuse_back
        } else {
            self.finish.diffuse
        }
    }

    /// The diffuse light from a light of colour `light` (already shadowed) at N.L `n_dot_l`;
    /// a light `behind` the surface shines through `diffuse`'s second value (POV-Ray 3.7's
    /// backside illumination, measured: pigment x back value x cos^brilliance x opacity).
    pub(super) fn diffuse(&self, n_dot_l: f64, light: DVec3, behind: bool) -> DVec3 {
        let f = self.finish;
        let amount = self.diffuse_value(behind);
        let diffuse = diffuse_term(amount, f.brilliance, n_dot_l, self.att, f.crand);
        self.pigment.rgb * light * diffuse
    }

    /// Phong and specular highlights of a light of colour `light` along `l`, seen along
    /// `d`; `None` where there is none.
    pub(super) fn highlight(&self, at: &LightAt, light: DVec3) -> Option<DVec3> {
        let f = self.finish;
        let (n, d, l) = (at.n, at.d, at.l);
        let highlight = phong_factor(f.phong, f.phong_size, n, d, l)
            + specular_factor(f.specular, f.roughness, n, d, l);
        (highlight > 0.0)
            .then(|| light * metallic_tint(f.metallic, self.pigment.rgb, at.n_dot_l) * highlight)
    }
}

/// The geometry of one light at one shading point.
#[derive(Clone, Copy, Debug)]
pub(super) struct LightAt {
    /// Shading normal facing the viewer, incoming direction, unit vector to the light.
    pub n: DVec3,
    pub d: DVec3,
    pub l: DVec3,
    /// N.L, made positive for a surface lit from behind.
    pub n_dot_l: f64,
    /// Lit from behind through `diffuse`'s second value (a double-illuminated surface is
    /// lit from behind as from the front, and is not `behind`).
    pub behind: bool,
}

/// A shadow test from one shading point towards one light.
pub(super) struct ShadowQuery<'l> {
    pub light: &'l PreparedLight,
    pub index: u32,
    /// The dimension block of the shading point (its trace level and diffuse bounces).
    pub level: u32,
    /// The shading point, to which an area light's grid is oriented.
    pub p: DVec3,
    /// Where shadow rays start: off the surface, on the light's side.
    pub origin: DVec3,
    /// The interiors that side is in.
    pub inside: &'l InteriorStack,
    /// The unshadowed light colour, which POV-Ray's adaptive rule compares.
    pub colour: DVec3,
}

impl Integrator<'_> {
    /// Ambient, emission and the direct light from every light source on one layer.
    pub(super) fn surface_light(
        &self,
        s: &Shading,
        layer: &ShadedLayer,
        memo: &mut ShadowMemo,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let mut colour = layer.ambient_and_emission(self.ambient_light);
        for (index, light) in self.scene.lights.iter().enumerate() {
            if !LightGroup::lights(light.group, s.material.light_group) {
                continue;
            }
            let lit = Lit {
                layer,
                index,
                memo: &mut *memo,
            };
            colour += match self.summed_grid(light) {
                Some(area) => self.grid_light(s, lit, area, sampler, counts),
                None => self.one_light(s, lit, sampler, counts),
            };
        }
        colour
    }

    /// The area light whose shading is summed over its grid: area_illumination in `pov`
    /// mode.
    fn summed_grid<'l>(&self, light: &'l PreparedLight) -> Option<&'l PreparedArea> {
        let summed = light.area_illumination
            && self.area_lights == AreaLightMode::Pov
            && self.quality >= super::QUALITY_AREA_LIGHTS;
        light.area.as_ref().filter(|_| summed)
    }

    /// Light `index` shading the layer from one direction, shadowed.
    fn one_light(
        &self,
        s: &Shading,
        lit: Lit,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let Lit { layer, index, memo } = lit;
        let light = &self.scene.lights[index];
        let Some(incidence) = self.incidence(s, light, index as u32, sampler) else {
            return DVec3::ZERO;
        };
        let back_lit = layer.finish.diffuse_back != 0.0;
        let Some(facing) = facing(s, incidence.l, back_lit) else {
            return DVec3::ZERO;
        };
        let colour = light.colour * incidence.factor;
        if colour == DVec3::ZERO {
            return DVec3::ZERO;
        }
        let filter = memo.filter(index, facing.flipped, || {
            let side = facing.flipped.then_some(incidence.l);
            self.side_shadow(s, (index, side), colour, &incidence, sampler, counts)
        });
        if filter == DVec3::ZERO {
            return DVec3::ZERO;
        }
        self.light_on_layer(s, layer, index, &facing.at, colour * filter)
    }

    /// area_illumination in `pov` mode: POV-Ray sums the finish over every grid point with
    /// equal weights, so each sample averages it over several points spread over the grid
    /// (`PreparedArea::shaded_points`; one point per sample left the grid's spread of
    /// directions as noise over every lit surface). The shadow rays are as for a light
    /// without it: the visibility is the grid's, tested once for each side of the surface
    /// the points light. Each point is as likely to be shaded as any other, its jitter
    /// uniform over its cell (and stratified over the pixel's samples:
    /// [`crate::render::sampler::CellJitter`]), so the expectation is POV-Ray's: the
    /// average shading of the grid times the visibility of its side.
    fn grid_light(
        &self,
        s: &Shading,
        lit: Lit,
        area: &PreparedArea,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let Lit { layer, index, memo } = lit;
        let light = &self.scene.lights[index];
        let p = s.surface.point;
        let back_lit = layer.finish.diffuse_back != 0.0;
        let dim = self
            .layout
            .dimension(s.path.block(), Purpose::LightShading(index as u32));
        sampler.set_dimension(dim);
        let s2 = sampler.get_2d();
        let cells = area
            .jitter
            .then(|| sampler.cell_jitter(dim, sampler.index()));
        let frame = area.frame(light.location, light.location - p);
        // Where one shadow ray is exact (a one-ray pixel), a small grid is shaded whole:
        // what is left of the sample's noise is then its position in the pixel. From a
        // budget of 1.25 samples per pixel on, everywhere.
        let small = area.size1 * area.size2 <= WHOLE_GRID_POINTS;
        let whole = (self.one_ray || self.whole_grid) && small;
        let points = if whole {
            area.size1 * area.size2
        } else {
            area.shaded_points()
        };
        // The shading of the points lighting the front, and of those lighting the back,
        // with the incidence of one of them (the side shadow rays start from).
        let mut sides = [(DVec3::ZERO, None); 2];
        let mut shade = |k: u32| {
            let jitter = cells.map_or((0.5, 0.5), |c| c.at(k));
            let at = area.point_at(&frame, k, jitter);
            let Some(incidence) = light.incidence_from(p, at) else {
                return;
            };
            let Some(facing) = facing(s, incidence.l, back_lit) else {
                return;
            };
            let colour = light.colour * incidence.factor;
            let side = &mut sides[usize::from(facing.flipped)];
            side.0 += self.light_on_layer(s, layer, index, &facing.at, colour);
            side.1 = Some(incidence);
        };
        if whole {
            (0..points).for_each(&mut shade);
        } else {
            area.spread_points(points, s2).for_each(&mut shade);
        }
        // The centre's light, which POV-Ray's adaptive rule compares.
        let centre = light
            .incidence(p)
            .map_or(light.colour, |c| light.colour * c.factor);
        let mut colour = DVec3::ZERO;
        for (flipped, (sum, incidence)) in sides.into_iter().enumerate() {
            if let Some(incidence) = incidence.filter(|_| sum != DVec3::ZERO) {
                colour += sum
                    * memo.filter(index, flipped == 1, || {
                        let side = (flipped == 1).then_some(incidence.l);
                        self.side_shadow(s, (index, side), centre, &incidence, sampler, counts)
                    });
            }
        }
        colour / f64::from(points)
    }

    /// What light `index` of colour `light` (shadowed) along `at` adds to the layer:
    /// diffuse and highlights, through the layer's iridescence.
    fn light_on_layer(
        &self,
        s: &Shading,
        layer: &ShadedLayer,
        index: usize,
        at: &LightAt,
        mut light: DVec3,
    ) -> DVec3 {
        if let Some(irid) = &layer.finish.irid {
            let wavelength = self.scene.settings.irid_wavelength;
            let n_dot_v = -at.n.dot(at.d);
            light *= irid_factor(irid, wavelength, at.n_dot_l, n_dot_v, s.surface.point);
        }
        let mut colour = layer.diffuse(at.n_dot_l, light, at.behind);
        // Radiosity rays see no highlights (measured: phong on a furnace's wall adds
        // only what the camera sees of it), nor does light through the back.
        if !self.scene.lights[index].shadowless
            && !at.behind
            && s.path.bounces == 0
            && let Some(h) = layer.highlight(at, light)
        {
            colour += h;
        }
        colour
    }

    /// The shadow test towards light `index` from the viewer's side of the surface, or
    /// from the other side, towards `behind`, where the light shines on the side the
    /// shading normal does not face: its shadow ray starts on the light's side, or it would
    /// cross the surface it leaves. That side's interiors are worked out only there.
    fn side_shadow(
        &self,
        s: &Shading,
        (index, behind): (usize, Option<DVec3>),
        colour: DVec3,
        incidence: &crate::render::lights::Incidence,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let beyond;
        let (origin, inside) = match behind {
            Some(l) => {
                beyond = super::crossing(s).2;
                (offset_point(s.surface.point, s.surface.normal, l), &beyond)
            }
            None => (s.shadow_origin, &s.path.interiors),
        };
        let query = ShadowQuery {
            light: &self.scene.lights[index],
            index: index as u32,
            level: s.path.block(),
            p: s.surface.point,
            origin,
            inside,
            colour,
        };
        self.shadowed(&query, incidence, sampler, counts)
    }

    /// The fraction of the light the query's point receives (all of it from a shadowless
    /// light, or below the quality that casts shadows).
    fn shadowed(
        &self,
        q: &ShadowQuery,
        incidence: &crate::render::lights::Incidence,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        if q.light.shadowless || self.quality < super::QUALITY_SHADOWS {
            return DVec3::ONE;
        }
        self.visibility(q, incidence.l, incidence.distance, sampler, counts)
    }

    /// Where the light comes from: its centre, or with area_illumination (in `continuous`
    /// mode) a point drawn uniformly, independently of the shadow test: the product of the
    /// average shading and the visibility.
    fn incidence(
        &self,
        s: &Shading,
        light: &PreparedLight,
        index: u32,
        sampler: &mut PixelSampler,
    ) -> Option<crate::render::lights::Incidence> {
        let p = s.surface.point;
        match &light.area {
            Some(area) if light.area_illumination && self.quality >= super::QUALITY_AREA_LIGHTS => {
                let dim = self
                    .layout
                    .dimension(s.path.block(), Purpose::LightShading(index));
                sampler.set_dimension(dim);
                let frame = area.frame(light.location, light.location - p);
                let at = area.sample_point(&frame, sampler.get_2d(), self.area_lights);
                light.incidence_from(p, at)
            }
            _ => light.incidence(p),
        }
    }

    /// The fraction of the light that reaches the shading point.
    pub(super) fn visibility(
        &self,
        q: &ShadowQuery,
        l: DVec3,
        distance: f64,
        sampler: &mut PixelSampler,
        counts: &mut RayCounts,
    ) -> DVec3 {
        let area = q.light.area.as_ref();
        let Some(area) = area.filter(|_| self.quality >= super::QUALITY_AREA_LIGHTS) else {
            counts.shadow += 1;
            return self.light_through(q, l, distance, Occlusion::Walk);
        };
        let dim = self
            .layout
            .dimension(q.level, Purpose::LightPosition(q.index));
        let pov = self.area_lights == AreaLightMode::Pov;
        let adaptive = area.adaptive.is_some() && pov && !self.one_ray;
        let rays = match self.light_samples {
            _ if adaptive => f64::from(area.agreeing),
            LightSamples::Cover if pov => cover_rays(area, sampler),
            LightSamples::Cover => 1.0,
            LightSamples::Fixed(n) => f64::from(n),
        };
        let shaft = self.shaft(q, area, rays);
        // Where nothing meets the shaft and nothing on the way alters the light, every ray
        // reaches it whole: a filter of one, each ray's and so every rule's over them.
        let free = shaft.as_ref().is_some_and(Occluders::is_empty) && !self.alters_light(q);
        // The item that stopped the last stopped shadow ray towards the grid, tested first
        // by the next ([`crate::geometry::World::occluded_hinted`]). Measured, bsp/Tango.pov
        // (an 8 x 8 adaptive area light over a lattice of boxes and CSG), 80x60, one
        // sample: 2,144 -> 1,471 M instructions; soft_shadow and area_adaptive (160x120,
        // 4 spp) +0.6% and -1.8% (640x480, 8 spp, one thread: soft_shadow 1.49-1.52 s
        // without, 1.51-1.53 s with it).
        let blocker = Cell::new(NO_ITEM);
        let occlusion = match &shaft {
            Some(among) => Occlusion::Among(among),
            None => Occlusion::Hinted(&blocker),
        };
        let mut shadow_to = |target: DVec3| {
            if free {
                counts.area_lit += 1;
                counts.spared += 1;
                return DVec3::ONE;
            }
            let to = target - q.origin;
            let dist = to.length();
            counts.shadow += 1;
            let filter = self.light_through(q, to / dist, dist, occlusion);
            counts.area_lit += u64::from(filter != DVec3::ZERO);
            counts.area_shadowed += u64::from(filter != DVec3::ONE);
            filter
        };
        if adaptive {
            if free {
                counts.area_lit += 1;
                counts.spared += u64::from(area.agreeing);
                return DVec3::ONE;
            }
            // POV-Ray's adaptive rule depends on what the corners see, so it is evaluated
            // as POV-Ray does, with jitter drawn from this sample.
            sampler.set_dimension(dim);
            let s = sampler.get_2d();
            let seed = ((s.0 * 4_294_967_296.0) as u64) << 32 | (s.1 * 4_294_967_296.0) as u64;
            let towards = q.light.location - q.p;
            return area.adaptive_filter(q.light.location, towards, q.colour, seed, shadow_to);
        }
        let n = match self.light_samples {
            LightSamples::Cover if pov => {
                return cover_grid(q, area, dim, sampler, &mut shadow_to);
            }
            LightSamples::Cover => 1,
            LightSamples::Fixed(n) => n,
        };
        sampler.set_dimension(dim);
        let s = sampler.get_2d();
        self.area_samples(q, area, s, n, &mut shadow_to)
    }

    /// The items that may stop the shadow rays from the query's point to the area light
    /// ([`crate::geometry::Shaft`]), where the point traces at least [`SHAFT_FROM_RAYS`]
    /// (`rays`: the fewest the adaptive rule tests, or about what a sample covers)
    /// towards it and shadows are all or nothing (no object
    /// transmits); `None` elsewhere or where the shaft meets too many items.
    fn shaft(&self, q: &ShadowQuery, area: &PreparedArea, rays: f64) -> Option<Occluders> {
        if rays < SHAFT_FROM_RAYS || self.scene.any_transmitting {
            return None;
        }
        let frame = area.frame(q.light.location, q.light.location - q.p);
        let shaft = Shaft::new(q.origin, area.extent(&frame, self.area_lights));
        self.scene.world.shaft_occluders(&shaft)
    }

    /// Whether something besides the objects changes the light on its way: a
    /// `projected_through` object, fog, media.
    fn alters_light(&self, q: &ShadowQuery) -> bool {
        let fog = q.light.media_attenuation && !self.scene.fogs.is_empty();
        let media = !self.scene.media.is_empty() && self.quality >= super::QUALITY_MEDIA;
        q.light.projected_through.is_some() || fog || media
    }

    /// What reaches the shading point along one shadow ray (`l` unit, `distance` to the
    /// light's point): the objects' filter, then the fog and media on the way.
    ///
    /// A light `projected_through` an object reaches the point only if the ray meets the
    /// object, and then as if it shone from that meeting point: objects beyond it do not
    /// shadow (measured: a box between such a light and its object leaves the projected
    /// spot lit, a box between the object and the wall shadows it; a copy of the object
    /// in the scene, where the ray meets it, does not shadow it).
    fn light_through(
        &self,
        q: &ShadowQuery,
        l: DVec3,
        distance: f64,
        occlusion: Occlusion,
    ) -> DVec3 {
        let distance = match &q.light.projected_through {
            None => distance,
            Some(stencil) => match stencil.intersect(&Ray::new(q.origin, l), distance, 0) {
                Some(hit) => hit.t,
                None => return DVec3::ZERO,
            },
        };
        let ray = Ray::new(q.origin, l);
        let filter = self.shadow_filter(&ray, distance * (1.0 - 1e-9), q, occlusion);
        if filter == DVec3::ZERO {
            return filter;
        }
        filter * self.through_atmosphere(q, l, distance)
    }

    /// What fog and media leave of the light over a shadow ray (`l` unit), stretch by
    /// stretch between the surfaces it crosses. The fogs act on a `media_attenuation`
    /// light only, on the stretches outside solid objects (measured: a disc inside a clear
    /// solid sphere of radius 5, lit from 20 away, receives exp(-15 / distance)); media as
    /// render::integrator::media says. The objects' media end at the last surface the ray
    /// crosses, as in POV-Ray 3.7: a light inside a medium reaches the points of that
    /// medium, and the surfaces in it, unattenuated over the stretch after the last
    /// crossing (measured: a box 10 below a light inside an absorbing sphere, absorption
    /// 0.1, is lit e = 2.76 times what the full path would leave; with a clear ball around
    /// the light only the stretch inside the ball goes free; a light outside the sphere is
    /// attenuated all the way to the sphere's surface).
    fn through_atmosphere(&self, q: &ShadowQuery, l: DVec3, distance: f64) -> DVec3 {
        let fogs = &self.scene.fogs;
        let fog = q.light.media_attenuation && !fogs.is_empty();
        let media = !self.scene.media.is_empty() && self.quality >= super::QUALITY_MEDIA;
        if !fog && !media {
            return DVec3::ONE;
        }
        let ray = Ray::new(q.origin, l);
        let mut hits = [(0.0, 0u32); MAX_CROSSINGS];
        let mut n = 0;
        self.scene.world.shadow_hits(&ray, distance, |hit| {
            hits[n] = (hit.t, self.scene.world.hit_material(hit));
            n += 1;
            n < MAX_CROSSINGS
        });
        let hits = &mut hits[..n];
        hits.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut interiors = *q.inside;
        let mut start = 0.0;
        let mut factor = DVec3::ONE;
        let ends = hits
            .iter()
            .map(|&(t, m)| (t, Some(m)))
            .chain([(distance, None)]);
        for (t, material) in ends {
            if interiors.in_atmosphere() && t > start {
                let segment = Segment {
                    origin: ray.at(start),
                    direction: l,
                    length: t - start,
                };
                if fog {
                    factor *= light_through_fog(fogs, &segment);
                }
                let media_inside = if material.is_some() {
                    &interiors
                } else {
                    &InteriorStack::OUTSIDE
                };
                factor *=
                    self.media_transmittance(&segment, media_inside, q.light.media_attenuation);
                if factor == DVec3::ZERO {
                    break;
                }
            }
            if let Some(m) = material.map(|m| &self.scene.materials[m as usize]) {
                interiors = if interiors.contains(m.interior_id) {
                    interiors.left(m.interior_id)
                } else {
                    interiors.entered(m.interior_id, m.interior.ior, m.hollow)
                };
            }
            start = t;
        }
        factor
    }

    /// `n` shadow samples of an area light: the stratified sample shifted by a well-spread
    /// set, so each is uniform and together they cover the light.
    fn area_samples(
        &self,
        q: &ShadowQuery,
        area: &PreparedArea,
        s: (f64, f64),
        n: u32,
        shadow_to: &mut dyn FnMut(DVec3) -> DVec3,
    ) -> DVec3 {
        let n = n.max(1);
        let frame = area.frame(q.light.location, q.light.location - q.p);
        let mut sum = DVec3::ZERO;
        for k in 0..n {
            let shift = (k as f64 / n as f64, (k as f64 * GOLDEN).fract());
            let sk = ((s.0 + shift.0).fract(), (s.1 + shift.1).fract());
            sum += shadow_to(area.sample_point(&frame, sk, self.area_lights));
        }
        sum / n as f64
    }

    /// The fraction of light that reaches along a shadow ray: zero at an opaque object, and
    /// `C * filter + transmit` per crossing of a filtering one (no refraction), as POV-Ray.
    /// `q.inside` holds the interiors the ray starts in: those of the ray that was shaded.
    fn shadow_filter(&self, ray: &Ray, t_max: f64, q: &ShadowQuery, occlusion: Occlusion) -> DVec3 {
        let inside = &q.inside;
        let photons = &q.light.photons;
        let scene = self.scene;
        if !scene.any_transmitting {
            let blocked = match occlusion {
                Occlusion::Walk => scene.world.occluded(ray, t_max),
                Occlusion::Hinted(hint) => scene.world.occluded_hinted(ray, t_max, hint),
                Occlusion::Among(among) => scene.world.occluded_among(among, ray, t_max),
            };
            return if blocked { DVec3::ZERO } else { DVec3::ONE };
        }
        let mut crossings = Crossings::default();
        let mut filter = DVec3::ONE;
        scene.world.shadow_hits(ray, t_max, |hit| {
            let index = scene.world.hit_material(hit);
            let mut material = &scene.materials[index as usize];
            if material.inner.is_some() {
                let back = scene.world.surface(ray, hit).normal.dot(ray.direction) > 0.0;
                material = scene.side_material(index, back);
            }
            // Where no photon was stored at all POV-Ray renders as without photons, the
            // targets' shadows filtered (measured: a glass target under a clear slab that
            // takes every photon first casts no shadow; beside a second, uncovered target
            // its shadow is black).
            let photon_shadow = material.photon_shadow && self.photons.is_some();
            if !material.transmits || photon_shadow && material.photons.stops_shadows(photons) {
                filter = DVec3::ZERO;
                return false;
            }
            let fades = material.interior.fade_power > 0.0 && material.interior.fade_distance > 0.0;
            if !crossings.count(hit.t, fades.then_some(index)) {
                return true;
            }
            let at = scene.world.texture_point(ray, hit);
            for layer in texture_layers(&material.texture, at) {
                let c = layer.colour;
                filter *= c.rgb * c.filter + DVec3::splat(c.transmit);
            }
            if material.interior.caustics != 0.0 {
                filter *= caustics_at(scene, ray, hit, material);
            }
            filter != DVec3::ZERO
        });
        if filter == DVec3::ZERO {
            return filter;
        }
        self.fade_along(ray, &mut crossings, inside, filter)
    }

    /// POV-Ray follows a shadow ray from crossing to crossing, and each crossing of an
    /// object either enters its interior or, when the ray is in it already, leaves it, and
    /// fades over the stretch since the previous crossing of any object, not since the
    /// interior was entered (measured: through a fading sphere holding a clear one, the
    /// shadow's centre fades only over the stretch above the clear one; through a union of
    /// two overlapping fading spheres, it fades over the two stretches from entering one to
    /// meeting the other, not over the whole chord; a merge fades over its whole chord).
    fn fade_along(
        &self,
        ray: &Ray,
        crossings: &mut Crossings,
        inside: &InteriorStack,
        mut filter: DVec3,
    ) -> DVec3 {
        if crossings.fading_len == 0 {
            return filter;
        }
        let mut interiors = Interiors::new(inside.ids());
        let counted = crossings.sorted();
        let speed = ray.direction.length();
        let mut previous = 0.0;
        for &(t, material) in counted {
            if let Some(index) = material {
                let material = &self.scene.materials[index as usize];
                if interiors.toggle(material.interior_id) {
                    filter *= fade(material, (t - previous) * speed);
                }
            }
            previous = t;
        }
        filter
    }
}

/// One light shading one texture layer, and the shadows found for the layers before.
struct Lit<'l, 'f> {
    layer: &'l ShadedLayer<'f>,
    index: usize,
    memo: &'l mut ShadowMemo,
}

/// A light along `l` (unit) as the shading point sees it, or `None` where it does not
/// light that side: a light behind the surface counts where the surface is
/// double-illuminated or `back_lit` (its diffuse has a second value).
fn facing(s: &Shading, l: DVec3, back_lit: bool) -> Option<Facing> {
    let n_dot_l = s.n.dot(l);
    let flipped = n_dot_l <= 0.0;
    let behind = flipped && !s.material.double_illuminate;
    if behind && !back_lit {
        return None;
    }
    let at = LightAt {
        n: s.n,
        d: s.d,
        l,
        n_dot_l: n_dot_l.abs(),
        behind,
    };
    Some(Facing { at, flipped })
}

/// A light's geometry at a shading point, and whether it is on the side the normal does
/// not face (where shadow rays start).
struct Facing {
    at: LightAt,
    flipped: bool,
}

/// The fake caustics of `material`'s interior where a shadow ray crosses its surface at
/// `hit`, from the angle to the perturbed normal ([`caustic_factor`]).
fn caustics_at(scene: &PreparedScene, ray: &Ray, hit: &Hit, material: &Material) -> f64 {
    let surface = scene.world.surface(ray, hit);
    let d = ray.direction.normalize();
    let facing = if surface.shading_normal.dot(d) > 0.0 {
        -surface.shading_normal
    } else {
        surface.shading_normal
    };
    let n = perturbed_normal(&material.texture, &surface, facing);
    caustic_factor(material.interior.caustics, n.dot(d))
}

/// About how many grid points one sample of [`cover_grid`] tests: the grid shared among
/// the pixel's samples, a cover per [`PreparedArea::cover_shared`] of them.
fn cover_rays(area: &PreparedArea, sampler: &PixelSampler) -> f64 {
    let n = sampler.samples_per_pixel();
    let covers = n.div_ceil(area.cover_shared());
    f64::from(area.size1 * area.size2) * f64::from(covers) / f64::from(n)
}

/// The light's grid shared out over the pixel's samples, each point tested as often as any
/// other and each sample weighing what it tests to the whole light. The grid's points lie
/// end to end on a line, each as long as its weight in POV-Ray's grid sum ([`WeightOrder`],
/// one random order per pixel); R = ceil(N / C) turns of that line are cut into N equal
/// blocks, and sample k tests the points of block pi(k) (pi a random permutation), each
/// counted by the length of it inside the block, over the block's length. So:
/// - each sample weighs its points to 1: a point fully lit or fully shadowed has no noise,
///   whatever the shading does across the pixel;
/// - over the pixel every point counts exactly R times its weight: a penumbra that does not
///   change across the pixel gives POV-Ray's grid sum exactly, and one that does changes
///   only through the positions each point is seen from, one more of them for every C
///   samples (`PreparedArea::cover_shared`: 16, or 2 for a jittered light);
/// - unbiased: pi(k) is any block with equal chance, and over the blocks each point counts
///   R times its weight, a 1/N share of it on average per block, block length R/N.
///
/// A jittered point's R tests in the pixel, one per turn, are stratified over its cell
/// ([`crate::render::sampler::CellJitter`]).
///
/// Each sample tests about K / min(N, C) + 1 points of a K-point grid.
fn cover_grid(
    q: &ShadowQuery,
    area: &PreparedArea,
    dim: u32,
    sampler: &PixelSampler,
    shadow_to: &mut dyn FnMut(DVec3) -> DVec3,
) -> DVec3 {
    let n = sampler.samples_per_pixel();
    let line = u128::from(n.div_ceil(area.cover_shared())) * u128::from(WeightOrder::TOTAL);
    let block = u128::from(permute(sampler.index(), n, sampler.pixel_seed(dim, 1)));
    let (start, end) = (
        line * block / u128::from(n),
        line * (block + 1) / u128::from(n),
    );
    let (start, end) = (start as u64, end as u64);
    let order = sampler.pixel_seed(dim, 0);
    // A jittered light's cell jitters for the turn being tested, drawn when it begins.
    let mut cells = None;
    let frame = area.frame(q.light.location, q.light.location - q.p);
    let mut sum = DVec3::ZERO;
    let mut at = start;
    while at < end {
        let round = (at / WeightOrder::TOTAL) as u32;
        let (point, stretch_end) = area
            .order
            .stretch_at(at, order ^ round.wrapping_mul(0x85eb_ca6b));
        let to = stretch_end.min(end);
        let offset = if area.jitter {
            let jitter = match cells {
                Some((r, jitter)) if r == round => jitter,
                _ => sampler.cell_jitter(dim, round),
            };
            cells = Some((round, jitter));
            jitter.at(point)
        } else {
            (0.5, 0.5)
        };
        sum += shadow_to(area.point_at(&frame, point, offset)) * (to - at) as f64;
        at = to;
    }
    sum * (f64::from(n) / line as f64)
}

/// What a shadow ray remembers of the transparent surfaces it crossed, in fixed arrays so
/// shadow rays allocate nothing.
#[derive(Default)]
struct Crossings {
    /// The crossings counted so far: their distances and, for a fading interior, the
    /// material. POV-Ray follows a shadow ray from crossing to crossing, so two faces at the
    /// same distance (a box and a cylinder of one object meeting face to face) filter it
    /// once (measured: iortest's figures match POV-Ray with a 0.01 gap or overlap but were
    /// darker where the faces touch).
    counted: [(f64, Option<u32>); MAX_CROSSINGS],
    counted_len: usize,
    /// How many of them fade.
    fading_len: usize,
}

impl Crossings {
    /// Records a crossing at `t`; false if one at the same distance was already counted.
    fn count(&mut self, t: f64, fading: Option<u32>) -> bool {
        let tie = 1e-9 * t.abs().max(1.0);
        if self.counted[..self.counted_len]
            .iter()
            .any(|&(c, _)| (c - t).abs() <= tie)
        {
            return false;
        }
        if self.counted_len < self.counted.len() {
            self.counted[self.counted_len] = (t, fading);
            self.counted_len += 1;
            self.fading_len += usize::from(fading.is_some());
        }
        true
    }

    /// The crossings in the order the ray meets them.
    fn sorted(&mut self) -> &[(f64, Option<u32>)] {
        let counted = &mut self.counted[..self.counted_len];
        counted.sort_by(|a, b| a.0.total_cmp(&b.0));
        counted
    }
}

/// The interiors a shadow ray is in, as a set it enters and leaves by crossing.
struct Interiors {
    ids: [u32; MAX_CROSSINGS],
    len: usize,
}

impl Interiors {
    fn new(start: &[u32]) -> Interiors {
        let mut ids = [u32::MAX; MAX_CROSSINGS];
        let len = start.len().min(MAX_CROSSINGS);
        ids[..len].copy_from_slice(&start[..len]);
        Interiors { ids, len }
    }

    /// Crosses a part of the object owning interior `id`: true if that leaves it.
    fn toggle(&mut self, id: u32) -> bool {
        if let Some(k) = self.ids[..self.len].iter().position(|&i| i == id) {
            self.ids.copy_within(k + 1..self.len, k);
            self.len -= 1;
            true
        } else {
            if self.len < self.ids.len() {
                self.ids[self.len] = id;
                self.len += 1;
            }
            false
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn layer(finish: &Finish) -> ShadedLayer<'_> {
        ShadedLayer {
            pigment: Colour::rgb(0.5, 0.25, 1.0),
            finish,
            att: 1.0,
        }
    }

    #[test]
    fn diffuse_is_pigment_times_light_times_n_dot_l() {
        let finish = Finish {
            diffuse: 0.6,
            ..Finish::default()
        };
        let d = layer(&finish).diffuse(0.5, DVec3::new(1.0, 2.0, 0.0), false);
        let expect = DVec3::new(0.5, 0.5, 0.0) * 0.6 * 0.5;
        assert!((d - expect).length() < 1e-12, "{d}");
        // Grazing or behind: nothing.
        assert_eq!(layer(&finish).diffuse(0.0, DVec3::ONE, false), DVec3::ZERO);
    }

    #[test]
    fn light_behind_shines_through_the_back_value() {
        let finish = Finish {
            diffuse: 0.6,
            diffuse_back: 0.3,
            brilliance: 3.0,
            ..Finish::default()
        };
        let d = layer(&finish).diffuse(0.5, DVec3::ONE, true);
        let expect = DVec3::new(0.5, 0.25, 1.0) * 0.3 * 0.5f64.powi(3);
        assert!((d - expect).length() < 1e-12, "{d}");
    }

    #[test]
    fn ambient_and_emission_scale_with_opacity() {
        let finish = Finish {
            ambient: DVec3::splat(0.2),
            emission: DVec3::splat(0.1),
            ..Finish::default()
        };
        let mut l = layer(&finish);
        l.att = 0.5;
        let c = l.ambient_and_emission(DVec3::splat(2.0));
        let expect = DVec3::new(0.5, 0.25, 1.0) * (0.2 * 2.0 + 0.1) * 0.5;
        assert!((c - expect).length() < 1e-12, "{c}");
    }

    #[test]
    fn highlights_peak_at_the_mirror_direction() {
        let finish = Finish {
            phong: 1.0,
            phong_size: 40.0,
            ..Finish::default()
        };
        let n = DVec3::Y;
        let d = DVec3::new(1.0, -1.0, 0.0).normalize();
        let mirror = DVec3::new(1.0, 1.0, 0.0).normalize();
        let at = |l: DVec3| LightAt {
            n,
            d,
            l,
            n_dot_l: n.dot(l),
            behind: false,
        };
        let peak = layer(&finish).highlight(&at(mirror), DVec3::ONE).unwrap();
        assert!((peak - DVec3::ONE).length() < 1e-12, "{peak}");
        let off = DVec3::new(-1.0, 1.0, 0.0).normalize();
        assert!(layer(&finish).highlight(&at(off), DVec3::ONE).is_none());
    }

    /// An area light of `n1` x `n2` points, 4 x 4 units, 10 above the origin (where the
    /// queries of `cover_samples` shade).
    fn grid_light(n1: u32, n2: u32, circular: bool) -> PreparedLight {
        let mut light = crate::scene::Light::point(DVec3::new(0.0, 10.0, 0.0), DVec3::ONE);
        light.area = Some(crate::scene::AreaLight {
            axis1: DVec3::X * 4.0,
            axis2: DVec3::Z * 4.0,
            size1: n1,
            size2: n2,
            adaptive: None,
            jitter: false,
            circular,
            orient: false,
        });
        PreparedLight::new(&light)
    }

    /// Each sample's value of `cover_grid` for a pixel of `n` samples, where a shadow ray
    /// is blocked when `blocked` says so of the point it goes to.
    fn cover_samples(
        light: &PreparedLight,
        n: u32,
        pixel: (u32, u32, u64),
        blocked: &dyn Fn(DVec3) -> bool,
    ) -> Vec<f64> {
        let area = light.area.as_ref().unwrap();
        let q = ShadowQuery {
            light,
            index: 0,
            level: 0,
            p: DVec3::ZERO,
            origin: DVec3::ZERO,
            inside: &InteriorStack::OUTSIDE,
            colour: DVec3::ONE,
        };
        let mut sampler = PixelSampler::new(n);
        (0..n)
            .map(|k| {
                sampler.start(pixel.0, pixel.1, k, pixel.2);
                let mut shadow_to = |at: DVec3| DVec3::splat(if blocked(at) { 0.0 } else { 1.0 });
                cover_grid(&q, area, 7, &sampler, &mut shadow_to).x
            })
            .collect()
    }

    /// POV-Ray's grid sum: each point's weight where it is not blocked.
    fn grid_sum(light: &PreparedLight, blocked: &dyn Fn(DVec3) -> bool) -> f64 {
        let area = light.area.as_ref().unwrap();
        let frame = area.frame(light.location, light.location);
        (0..area.size1 * area.size2)
            .map(|g| area.weighted_point(&frame, g, (0.5, 0.5)))
            .map(|(at, w)| if blocked(at) { 0.0 } else { w })
            .sum()
    }

    #[test]
    fn a_pixel_covering_the_grid_sums_it_exactly() {
        // Blocked on one side of a line across the light: a penumbra that does not change
        // across the pixel. Whatever the sample count, the pixel's mean is the grid sum,
        // and with nothing blocked every sample alone gives the whole light.
        let blocked = |at: DVec3| at.x + 0.3 * at.z > 0.4;
        for (n1, n2, circular) in [(9, 9, true), (5, 5, false), (6, 2, false), (1, 3, false)] {
            let light = grid_light(n1, n2, circular);
            let exact = grid_sum(&light, &blocked);
            assert!(exact > 0.05 && exact < 0.95, "{n1}x{n2}: {exact}");
            for n in [1, 3, 4, 7, 16, 40, 81, 100, 256] {
                let samples = cover_samples(&light, n, (3, 5, 11), &blocked);
                let mean = samples.iter().sum::<f64>() / f64::from(n);
                assert!(
                    (mean - exact).abs() < 1e-12,
                    "{n1}x{n2}, {n} spp: {mean} vs {exact}"
                );
                for lit in cover_samples(&light, n, (3, 5, 11), &|_| false) {
                    assert!((lit - 1.0).abs() < 1e-8, "{n1}x{n2}, {n} spp: {lit}");
                }
            }
        }
    }

    #[test]
    fn each_sample_of_the_cover_is_unbiased() {
        // Sample k alone, over many pixels, averages to the grid sum: which points it
        // tests does not depend on k. 4000 pixels: the mean is within 4 standard errors.
        // With 16 and with 48 samples (the grid covered three times).
        let blocked = |at: DVec3| at.x > 0.2 || at.z < -1.1;
        let light = grid_light(9, 9, true);
        let exact = grid_sum(&light, &blocked);
        for (n, k) in [(16, 0), (16, 5), (16, 15), (48, 40)] {
            let values: Vec<f64> = (0..4000)
                .map(|p| cover_samples(&light, n, (p % 64, p / 64, 3), &blocked)[k as usize])
                .collect();
            let m = values.len() as f64;
            let mean = values.iter().sum::<f64>() / m;
            let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (m - 1.0);
            let se = (var / m).sqrt();
            assert!(
                (mean - exact).abs() < 4.0 * se,
                "sample {k}: {mean} vs {exact} (se {se})"
            );
        }
    }

    #[test]
    fn coinciding_shadow_crossings_count_once() {
        let mut c = Crossings::default();
        assert!(c.count(2.0, None));
        assert!(!c.count(2.0 + 1e-12, None));
        assert!(c.count(2.001, None));
    }

    #[test]
    fn crossing_an_interior_enters_or_leaves_it() {
        let mut inside = Interiors::new(&[3]);
        assert!(inside.toggle(3));
        assert!(!inside.toggle(5));
        assert!(!inside.toggle(3));
        assert!(inside.toggle(5));
        assert!(inside.toggle(3));
        assert!(!inside.toggle(3));
    }
}
