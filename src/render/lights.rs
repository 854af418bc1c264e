//! Lights prepared for sampling. In `pov` mode an area light's estimator has exactly the
//! expectation of POV-Ray's grid: a grid point is drawn with the weight POV-Ray's recursive
//! corner averaging gives it, so the mean visibility equals POV-Ray's shadow fraction.

use glam::DVec3;

use crate::scene::{Light, LightKind};

/// Spreads several light samples: point k of n is shifted by (k/n, k * golden ratio mod 1),
/// a well-spread 2D set for any n.
pub const GOLDEN: f64 = 0.618_033_988_749_894_9;

#[derive(Clone, Debug)]
pub struct PreparedLight {
    pub kind: LightKind,
    pub location: DVec3,
    pub colour: DVec3,
    pub shadowless: bool,
    pub fade_distance: f64,
    pub fade_power: f64,
    pub area: Option<PreparedArea>,
    pub area_illumination: bool,
    pub media_attenuation: bool,
    /// Whether scattering media see the light: not with `media_interaction off`, and
    /// never from a shadowless light (measured: a shadowless light lights no media).
    pub lights_media: bool,
    /// The `light_group` it belongs to (`None`: global).
    pub group: Option<u32>,
    pub photons: crate::scene::LightPhotons,
    /// `projected_through`'s object, built for ray tests.
    pub projected_through: Option<std::sync::Arc<crate::geometry::World>>,
}

#[derive(Clone, Debug)]
pub struct PreparedArea {
    pub axis1: DVec3,
    pub axis2: DVec3,
    pub size1: u32,
    pub size2: u32,
    pub jitter: bool,
    pub circular: bool,
    pub orient: bool,
    /// `adaptive k`: POV-Ray's data-dependent subdivision, reproduced per shaded point.
    pub adaptive: Option<u32>,
    /// Cumulative grid weights along each axis; the last entry is 1.
    cdf1: Vec<f64>,
    cdf2: Vec<f64>,
    /// The grid's points by weight, for covering it a pixel at a time.
    pub order: WeightOrder,
    /// The points the adaptive rule tests where all agree
    /// ([`PreparedArea::points_when_agreeing`]).
    pub agreeing: u32,
}

/// A light grid's points laid end to end on a line of length [`WeightOrder::TOTAL`], each
/// taking a stretch as long as its weight in POV-Ray's grid sum, grouped by weight: the
/// weights are POV-Ray's halvings, so each is a whole number of units and the classes are
/// few (three for 9 x 9). Which point of a class a stretch holds is left to a permutation.
#[derive(Clone, Debug)]
pub struct WeightOrder {
    /// Point indices (row-major over the grid), class by class.
    points: Vec<u32>,
    classes: Vec<WeightClass>,
}

/// Points of one weight: `points[first..first + len]`, each `units` long, from `start` on
/// the line.
#[derive(Clone, Copy, Debug)]
struct WeightClass {
    first: u32,
    len: u32,
    units: u64,
    start: u64,
}

impl WeightOrder {
    /// The line's length: weights in units of 2^-32.
    pub const TOTAL: u64 = 1 << 32;

    fn new(w1: &[f64], w2: &[f64]) -> WeightOrder {
        let units = |w: f64| (w * Self::TOTAL as f64).round() as u64;
        let mut by_weight: Vec<(u64, u32)> = (0..w1.len() * w2.len())
            .map(|g| (units(w1[g % w1.len()] * w2[g / w1.len()]), g as u32))
            .filter(|&(u, _)| u > 0)
            .collect();
        by_weight.sort_unstable_by_key(|&(u, g)| (std::cmp::Reverse(u), g));
        let mut classes: Vec<WeightClass> = Vec::new();
        let mut start = 0;
        for (i, &(u, _)) in by_weight.iter().enumerate() {
            match classes.last_mut() {
                Some(c) if c.units == u => c.len += 1,
                _ => classes.push(WeightClass {
                    first: i as u32,
                    len: 1,
                    units: u,
                    start,
                }),
            }
            start += u;
        }
        WeightOrder {
            points: by_weight.into_iter().map(|(_, g)| g).collect(),
            classes,
        }
    }

    /// The point whose stretch holds position `at` of the line (taken modulo its
    /// length), with the points of each class in the order `permute(_, len, seed)` gives
    /// them, and where that stretch ends (on the same unrolled line as `at`).
    pub fn stretch_at(&self, at: u64, seed: u32) -> (u32, u64) {
        let (round, u) = (at / Self::TOTAL, at % Self::TOTAL);
        let last = self.classes.len() - 1;
        let c = self
            .classes
            .iter()
            .position(|c| u < c.start + c.len as u64 * c.units);
        let class = self.classes[c.unwrap_or(last)];
        let q = (u.saturating_sub(class.start) / class.units).min(class.len as u64 - 1);
        let seed = seed ^ class.first.wrapping_mul(0x9e37_79b9);
        let point = super::sampler::permute(q as u32, class.len, seed);
        // Past the last class (rounding left the line's end short of TOTAL): to the end.
        let end = match c {
            Some(_) => round * Self::TOTAL + class.start + (q + 1) * class.units,
            None => (round + 1) * Self::TOTAL,
        };
        (self.points[(class.first + point) as usize], end)
    }
}

/// How many of a pixel's samples share one cover of an area light's grid: each further
/// `COVER_SHARED` samples cover it once more. Within a penumbra each grid point's shadow
/// edge crosses some pixels, and a pixel that tests that point once sees it at one position
/// only; testing every point again as the samples grow lets that noise fall with them
/// (at 640x480 under a 9x9 light, one cover for all of 32 samples left their noise at 0.0013
/// where 16 samples had 0.0015).
pub const COVER_SHARED: u32 = 16;

/// The same for a jittered light, whose points move at each test: there, testing each
/// point again is what lets the jitter's noise fall. Measured on
/// scenes/area_illumination.pov (7 x 3, jittered), 640x480 adaptive, RMSE^2 x seconds at
/// 8/16/32 spp: every 16 samples 5.3e-5 at 16 spp (half the pixels' error, the smooth
/// lit ones, was the jitter's), every 8 4.5/5.0/5.2e-5, every 4 3.9/3.8/4.1e-5, every 2
/// 3.4/3.5/4.0e-5, every sample 4.1e-5 at 16 spp.
pub const COVER_SHARED_JITTERED: u32 = 2;

/// How many shadow rays an area light gets per shading point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightSamples {
    /// This many, spread over the light from the sample's stratified position.
    Fixed(u32),
    /// With POV-Ray's grid (`--area-lights pov`), as many as it takes for a pixel's samples
    /// together to test every grid point, by weight, once for every
    /// [`PreparedArea::cover_shared`] of them: POV-Ray's shadow rays per pixel, shared
    /// among the pixel's samples instead of spent on each (`cover_grid` in the
    /// integrator). Otherwise one.
    Cover,
}

/// Covering the grid is the default: at 640x480 it made soft shadows 2-3x cheaper to a
/// given noise than one shadow ray per sample, and never worse (docs/convergence.md).
impl Default for LightSamples {
    fn default() -> Self {
        LightSamples::Cover
    }
}

impl std::str::FromStr for LightSamples {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        if s == "cover" {
            return Ok(LightSamples::Cover);
        }
        match s.parse::<u32>() {
            Ok(n) if n >= 1 => Ok(LightSamples::Fixed(n)),
            _ => Err(format!(
                "expected a count of at least 1 or `cover`, found `{s}`"
            )),
        }
    }
}

impl PreparedLight {
    pub fn new(light: &Light) -> PreparedLight {
        let area = light.area.map(|a| PreparedArea {
            axis1: a.axis1,
            axis2: a.axis2,
            size1: a.size1.max(1),
            size2: a.size2.max(1),
            jitter: a.jitter,
            circular: a.circular,
            orient: a.orient,
            adaptive: a.adaptive,
            cdf1: cumulative(&grid_weights(a.size1.max(1))),
            cdf2: cumulative(&grid_weights(a.size2.max(1))),
            order: WeightOrder::new(&grid_weights(a.size1.max(1)), &grid_weights(a.size2.max(1))),
            agreeing: 0,
        });
        let area = area.map(|mut a| {
            a.agreeing = a.points_when_agreeing();
            a
        });
        PreparedLight {
            kind: light.kind,
            location: light.location,
            colour: light.colour,
            shadowless: light.shadowless,
            fade_distance: light.fade_distance,
            fade_power: light.fade_power,
            area,
            area_illumination: light.area_illumination && light.area.is_some(),
            media_attenuation: light.media_attenuation,
            lights_media: light.media_interaction && !light.shadowless,
            group: light.group,
            photons: light.photons,
            projected_through: light.projected_through.as_ref().map(|o| o.0.clone()),
        }
    }

    /// `fade_distance` and `fade_power`'s factor at `distance` from the light.
    pub fn fade(&self, distance: f64) -> f64 {
        if self.fade_power > 0.0 && self.fade_distance > 0.0 {
            2.0 / (1.0 + (distance / self.fade_distance).powf(self.fade_power))
        } else {
            1.0
        }
    }

    /// Where the light comes from as seen from `p`, how far a shadow ray must go, and the
    /// factor (fade, spotlight cone, cylinder) on its colour before shadows; `None` where the
    /// light cannot reach (outside a cone or cylinder): no shadow ray is spent there.
    pub fn incidence(&self, p: DVec3) -> Option<Incidence> {
        self.incidence_from(p, self.location)
    }

    /// As [`Self::incidence`], with the light moved to `location` (one point of an area
    /// light, for area_illumination).
    pub fn incidence_from(&self, p: DVec3, location: DVec3) -> Option<Incidence> {
        let (l, distance, fade_distance) = match self.kind {
            LightKind::Parallel { point_at } | LightKind::Cylinder { point_at, .. } => {
                let l = (location - point_at).normalize_or(DVec3::Y);
                // Shadows reach back to the plane through the light, across its direction;
                // fading is measured along the axis too.
                let along = (location - p).dot(l).max(0.0);
                (l, along, along)
            }
            LightKind::Point | LightKind::Spot { .. } => {
                let to = location - p;
                let d = to.length();
                if d.is_nan() || d <= 0.0 {
                    return None;
                }
                (to / d, d, d)
            }
        };
        let mut factor = self.fade(fade_distance);
        match self.kind {
            LightKind::Spot {
                point_at,
                radius,
                falloff,
                tightness,
            } => {
                let axis = (point_at - location).normalize_or(DVec3::Z);
                let cos = (-l).dot(axis);
                let cos_radius = radius.to_radians().cos();
                let cos_falloff = falloff.to_radians().cos();
                if cos < cos_falloff {
                    return None;
                }
                if tightness > 0.0 {
                    factor *= cos.max(0.0).powf(tightness);
                }
                if cos < cos_radius {
                    factor *= smoothstep((cos - cos_falloff) / (cos_radius - cos_falloff));
                }
            }
            LightKind::Cylinder {
                radius,
                falloff,
                tightness,
                ..
            } => {
                let rel = p - location;
                let off_axis = (rel - rel.dot(-l) * -l).length();
                if off_axis >= falloff {
                    return None;
                }
                if tightness > 0.0 {
                    factor *= (1.0 - off_axis / falloff).powf(tightness);
                }
                if off_axis > radius {
                    factor *= smoothstep((falloff - off_axis) / (falloff - radius));
                }
            }
            LightKind::Point | LightKind::Parallel { .. } => {}
        }
        (factor > 0.0).then_some(Incidence {
            l,
            distance,
            factor,
        })
    }
}

/// Light arriving at a point, before shadows.
#[derive(Clone, Copy, Debug)]
pub struct Incidence {
    /// Unit vector towards the light.
    pub l: DVec3,
    /// How far a shadow ray must reach.
    pub distance: f64,
    pub factor: f64,
}

fn smoothstep(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// An area light's centre and (oriented) axes as one shading point sees them.
#[derive(Clone, Copy, Debug)]
pub struct AreaFrame {
    pub centre: DVec3,
    pub axis1: DVec3,
    pub axis2: DVec3,
}

impl PreparedArea {
    /// A point of the light to shadow-test, from the stratified pair (s1, s2). In `pov`
    /// mode it is a grid point drawn with POV-Ray's weights, jittered by where s fell inside
    /// its grid cell's weight, which keeps the jitter uniform and stratified. In `continuous`
    /// mode it is uniform over the light's parallelogram (or disc, if circular).
    pub fn sample_point(
        &self,
        frame: &AreaFrame,
        (s1, s2): (f64, f64),
        mode: AreaLightMode,
    ) -> DVec3 {
        let (u, v) = match mode {
            AreaLightMode::Continuous => {
                if self.circular {
                    let (x, y) = super::sampler::concentric_disc(s1, s2);
                    (0.5 * x, 0.5 * y)
                } else {
                    (s1 - 0.5, s2 - 0.5)
                }
            }
            AreaLightMode::Pov => {
                let ((i1, r1), (i2, r2)) = (pick(&self.cdf1, s1), pick(&self.cdf2, s2));
                (
                    grid_coordinate(i1, self.size1, self.jitter.then_some(r1)),
                    grid_coordinate(i2, self.size2, self.jitter.then_some(r2)),
                )
            }
        };
        if mode == AreaLightMode::Continuous {
            // Already inside the disc for circular lights.
            return frame.centre + frame.axis1 * u + frame.axis2 * v;
        }
        self.place(frame, u, v)
    }

    /// How many of a pixel's samples share one cover of the grid.
    pub fn cover_shared(&self) -> u32 {
        if self.jitter {
            COVER_SHARED_JITTERED
        } else {
            COVER_SHARED
        }
    }

    /// How many grid points an area_illumination light shades each sample from: one per
    /// index along the longer axis, and a multiple of that size of at least 6 (all of a small
    /// grid), so that every index gets as many. Measured on scenes/area_illumination.pov
    /// (7 x 3) at 640x480, RMSE^2 x seconds at 4 spp: 4 points 7.1e-5, 7 points 5.5e-5, 8
    /// points 5.9e-5, 10 points 6.1e-5, all 21 6.6e-5; one point 3.4e-4. (That was before
    /// the cells' jitter was stratified; since, grids of up to 81 points are shaded whole
    /// from 1.25 spp on, `WHOLE_GRID_FROM_SPP`, and these points serve cheaper renders.)
    pub fn shaded_points(&self) -> u32 {
        let long = self.size1.max(self.size2).max(1);
        (long * 6_u32.div_ceil(long)).min(self.size1 * self.size2)
    }

    /// `count` grid points spread over the grid from the pair (u, w), each point as likely
    /// to be among them as any other (count / points, as for any systematic sample): along
    /// the grid's longer axis at equal steps from u, `count` / size positions per index;
    /// along the other, a golden-ratio sequence from w. So an average over them has the
    /// expectation of the average over the whole grid, and when (u, w) are stratified over
    /// a pixel's samples, so are the points.
    pub fn spread_points(&self, count: u32, (u, mut w): (f64, f64)) -> impl Iterator<Item = u32> {
        let long_first = self.size1 >= self.size2;
        let (na, nb) = if long_first {
            (self.size1, self.size2)
        } else {
            (self.size2, self.size1)
        };
        let step = f64::from(na) / f64::from(count.max(1));
        let size1 = self.size1;
        (0..count).map(move |j| {
            let a = (((u + f64::from(j)) * step) as u32).min(na - 1);
            let b = ((w * f64::from(nb)) as u32).min(nb - 1);
            w += GOLDEN;
            if w >= 1.0 {
                w -= 1.0;
            }
            if long_first {
                a + b * size1
            } else {
                b + a * size1
            }
        })
    }

    /// Grid point `point` (row-major over size1 x size2), jittered by `jitter` where the
    /// light has jitter.
    pub fn point_at(&self, frame: &AreaFrame, point: u32, jitter: (f64, f64)) -> DVec3 {
        let (i, j) = ((point % self.size1) as usize, (point / self.size1) as usize);
        self.grid_point(frame, i, j, jitter)
    }

    /// [`Self::point_at`] with the point's weight in POV-Ray's grid sum: for tests that
    /// compute that sum exactly.
    #[cfg(test)]
    pub fn weighted_point(
        &self,
        frame: &AreaFrame,
        point: u32,
        jitter: (f64, f64),
    ) -> (DVec3, f64) {
        let (i, j) = ((point % self.size1) as usize, (point / self.size1) as usize);
        let weight = cell_weight(&self.cdf1, i) * cell_weight(&self.cdf2, j);
        (self.point_at(frame, point, jitter), weight)
    }

    /// The light's centre and axes as seen from one shading point (`towards` points from it
    /// to the centre; `orient` turns the axes to face it), computed once for all of that
    /// point's shadow rays.
    pub fn frame(&self, centre: DVec3, towards: DVec3) -> AreaFrame {
        let (axis1, axis2) = self.orient_axes(towards);
        AreaFrame {
            centre,
            axis1,
            axis2,
        }
    }

    /// Corners, in order around it, of a quadrilateral that holds every point of the light
    /// `frame` places ([`Self::sample_point`], [`Self::point_at`]): the grid grown by half
    /// a cell where it jitters, by the circular mapping's shift, and by a trillionth for
    /// rounding. For shaft culling ([`crate::geometry::Shaft`]).
    pub fn extent(&self, frame: &AreaFrame, mode: AreaLightMode) -> [DVec3; 4] {
        let reach = |n: u32| match mode {
            AreaLightMode::Continuous => 0.5,
            AreaLightMode::Pov if n <= 1 => 0.0,
            AreaLightMode::Pov if self.jitter => 0.5 + 0.5 / f64::from(n - 1),
            AreaLightMode::Pov => 0.5,
        };
        let shift = if self.circular { 0.001 } else { 0.0 };
        let grown = |n: u32| (reach(n) + shift) * (1.0 + 1e-12);
        let (u, v) = (grown(self.size1), grown(self.size2));
        let at = |su: f64, sv: f64| frame.centre + frame.axis1 * (su * u) + frame.axis2 * (sv * v);
        [at(-1.0, -1.0), at(1.0, -1.0), at(1.0, 1.0), at(-1.0, 1.0)]
    }

    /// The light position for grid coordinates (u, v) in [-1/2, 1/2]: POV-Ray's circular
    /// mapping and orient.
    fn place(&self, frame: &AreaFrame, mut u: f64, mut v: f64) -> DVec3 {
        if self.circular {
            u += 0.001;
            v += 0.001;
            let len = (u * u + v * v).sqrt();
            let s = u.abs().max(v.abs()) / len;
            u *= s;
            v *= s;
        }
        frame.centre + frame.axis1 * u + frame.axis2 * v
    }

    fn orient_axes(&self, towards: DVec3) -> (DVec3, DVec3) {
        if !self.orient {
            return (self.axis1, self.axis2);
        }
        let d = towards.normalize_or(DVec3::Z);
        let z = if (d.z.abs() - 1.0).abs() < 0.01 {
            DVec3::Y
        } else {
            DVec3::Z
        };
        let len = self.axis1.length();
        let a1 = d.cross(z).normalize_or(DVec3::X) * len;
        let a2 = d.cross(a1).normalize_or(DVec3::Y) * len;
        (a1, a2)
    }
}

impl PreparedArea {
    /// The grid point (i, j), jittered by `jitter` (each component in [0, 1)), with
    /// circular and orient applied.
    fn grid_point(&self, frame: &AreaFrame, i: usize, j: usize, jitter: (f64, f64)) -> DVec3 {
        let u = grid_coordinate(i, self.size1, self.jitter.then_some(jitter.0));
        let v = grid_coordinate(j, self.size2, self.jitter.then_some(jitter.1));
        self.place(frame, u, v)
    }

    /// How many grid points [`Self::adaptive_filter`] tests where every test agrees (all
    /// the light arrives): the corners, and the points of the splits its level forces (a
    /// 9 x 9 grid at `adaptive 1`: 3 x 3); the fewest any shading point tests. Counted by
    /// running the rule once; 0 for a light without `adaptive`.
    fn points_when_agreeing(&self) -> u32 {
        if self.adaptive.is_none() {
            return 0;
        }
        let mut tested = 0;
        self.adaptive_filter(DVec3::ZERO, DVec3::Y, DVec3::ONE, 0, |_| {
            tested += 1;
            DVec3::ONE
        });
        tested
    }

    /// POV-Ray's adaptive shadow test, reproduced exactly for one shaded point: corners of
    /// grid rectangles are tested (each grid point once, jittered afresh from `seed`), and a
    /// rectangle is split while it is above the adaptive level or its neighbouring corners
    /// disagree by more than 0.1 (sum over channels of the shadowed light colour). Returns
    /// the shadow filter (visible fraction per channel). `filter_to` traces one shadow ray.
    pub fn adaptive_filter(
        &self,
        centre: DVec3,
        towards: DVec3,
        light_colour: DVec3,
        seed: u64,
        filter_to: impl FnMut(DVec3) -> DVec3,
    ) -> DVec3 {
        let (n1, n2) = (self.size1 as usize, self.size2 as usize);
        let limit = self.adaptive.unwrap_or(100);
        let frame = self.frame(centre, towards);
        ADAPTIVE_CACHE.with(|cache| {
            let mut cache = cache.borrow_mut();
            cache.clear();
            cache.resize(n1 * n2, None);
            let mut grid = GridTests {
                area: self,
                frame,
                seed,
                cache: &mut cache,
                filter_to,
                colour: light_colour,
                limit,
            };
            let (u2, v2) = (n1 - 1, n2 - 1);
            let corners = [
                grid.get(0, 0),
                grid.get(u2, 0),
                grid.get(0, v2),
                grid.get(u2, v2),
            ];
            grid.rect((0, 0, u2, v2), corners, 0)
        })
    }
}

/// One shading point's adaptive shadow test ([`PreparedArea::adaptive_filter`]): the grid
/// points tested so far, and how to test another.
struct GridTests<'a, F> {
    area: &'a PreparedArea,
    frame: AreaFrame,
    seed: u64,
    cache: &'a mut [Option<DVec3>],
    filter_to: F,
    colour: DVec3,
    limit: u32,
}

impl<F: FnMut(DVec3) -> DVec3> GridTests<'_, F> {
    /// Grid point (i, j)'s shadow filter: tested once, then remembered. The lookup is
    /// inline and the test is not: most lookups (three in four on scenes/area_adaptive.pov)
    /// find the point tested, and a call per lookup, with its entry and exit, was 8% of
    /// that scene's instructions.
    #[inline(always)]
    fn get(&mut self, i: usize, j: usize) -> DVec3 {
        match self.cache[j * self.area.size1 as usize + i] {
            Some(f) => f,
            None => self.test(i, j),
        }
    }

    #[inline(never)]
    fn test(&mut self, i: usize, j: usize) -> DVec3 {
        let k = j * self.area.size1 as usize + i;
        let mut rng = rand_pcg::Pcg32::new(
            self.seed ^ (k as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15),
            0xda3e_39cb_94b9_5bdb,
        );
        let jitter = (unit(&mut rng), unit(&mut rng));
        let f = (self.filter_to)(self.area.grid_point(&self.frame, i, j, jitter));
        self.cache[k] = Some(f);
        f
    }

    /// The filter over the grid rectangle (u1, v1)-(u2, v2) whose corners' filters are
    /// `c` (in the order (u1, v1), (u2, v1), (u1, v2), (u2, v2)): their mean, or the mean
    /// of its four quarters where it is split. A quarter takes its corners from `c` where
    /// they are the rectangle's, so only the new points are looked up.
    fn rect(
        &mut self,
        (u1, v1, u2, v2): (usize, usize, usize, usize),
        c: [DVec3; 4],
        level: u32,
    ) -> DVec3 {
        let differ = |a: DVec3, b: DVec3| ((a - b) * self.colour).abs().element_sum() > 0.1;
        let [c00, c10, c01, c11] = c;
        let spans = u2 - u1 > 1 || v2 - v1 > 1;
        let split = spans
            && (level < self.limit
                || differ(c00, c10)
                || differ(c00, c01)
                || differ(c10, c11)
                || differ(c01, c11));
        if !split {
            return (c00 + c10 + c01 + c11) * 0.25;
        }
        let (ua, ub) = ((u1 + u2) / 2, (u1 + u2).div_ceil(2));
        let (va, vb) = ((v1 + v2) / 2, (v1 + v2).div_ceil(2));
        let low = [c00, self.get(ua, v1), self.get(u1, va), self.get(ua, va)];
        let right = [self.get(ub, v1), c10, self.get(ub, va), self.get(u2, va)];
        let high = [self.get(u1, vb), self.get(ua, vb), c01, self.get(ua, v2)];
        let far = [self.get(ub, vb), self.get(u2, vb), self.get(ub, v2), c11];
        (self.rect((u1, v1, ua, va), low, level + 1)
            + self.rect((ub, v1, u2, va), right, level + 1)
            + self.rect((u1, vb, ua, v2), high, level + 1)
            + self.rect((ub, vb, u2, v2), far, level + 1))
            * 0.25
    }
}

thread_local! {
    /// Shadow results per grid point for the adaptive test, reused from point to point.
    static ADAPTIVE_CACHE: std::cell::RefCell<Vec<Option<DVec3>>> = const { std::cell::RefCell::new(Vec::new()) };
}

fn unit(rng: &mut rand_pcg::Pcg32) -> f64 {
    use rand::Rng;
    (rng.next_u32() as f64 + 0.5) / 4_294_967_296.0
}

/// How area lights are sampled (`--area-lights`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AreaLightMode {
    /// POV-Ray's grid: the expectation is exactly POV-Ray's image.
    #[default]
    Pov,
    /// The ideal emitter the grid approximates, for accuracy studies.
    Continuous,
}

/// Position along one axis in [-1/2, 1/2]: grid index `i` of `n`, plus jitter of up to half
/// a cell either way (`r` uniform in [0, 1)). A single row has no offset.
fn grid_coordinate(i: usize, n: u32, jitter: Option<f64>) -> f64 {
    if n <= 1 {
        return 0.0;
    }
    let j = jitter.map_or(0.0, |r| r - 0.5);
    (i as f64 + j) / (n - 1) as f64 - 0.5
}

/// Index drawn by `s` from a cumulative table, and where `s` fell inside that entry (0..1).
fn pick(cdf: &[f64], s: f64) -> (usize, f64) {
    let i = cdf.partition_point(|&c| c <= s).min(cdf.len() - 1);
    let lo = if i == 0 { 0.0 } else { cdf[i - 1] };
    let w = cdf[i] - lo;
    let r = if w > 0.0 {
        ((s - lo) / w).clamp(0.0, 1.0 - f64::EPSILON)
    } else {
        0.5
    };
    (i, r)
}

/// Entry `i`'s weight in a cumulative table.
#[cfg(test)]
fn cell_weight(cdf: &[f64], i: usize) -> f64 {
    cdf[i] - if i == 0 { 0.0 } else { cdf[i - 1] }
}

fn cumulative(w: &[f64]) -> Vec<f64> {
    let mut acc = 0.0;
    let mut out: Vec<f64> = w
        .iter()
        .map(|x| {
            acc += x;
            acc
        })
        .collect();
    if let Some(last) = out.last_mut() {
        *last = 1.0;
    }
    out
}

/// The weight of each grid index along one axis of POV-Ray's non-adaptive area light.
/// POV-Ray averages a rectangle's four corners, or, when it spans more than one cell, the
/// values of the four halves split at floor/ceil of the midpoint. That recursion is
/// separable, so one axis is enough: [lo, hi] splits into [lo, floor(m)] and [ceil(m), hi],
/// each with half the weight, until it spans at most one cell.
pub fn grid_weights(n: u32) -> Vec<f64> {
    let n = n.max(1) as usize;
    let mut w = vec![0.0; n];
    fn split(lo: usize, hi: usize, weight: f64, w: &mut [f64]) {
        if hi - lo <= 1 {
            w[lo] += weight * 0.5;
            w[hi] += weight * 0.5;
        } else {
            let m = (lo + hi) as f64 * 0.5;
            split(lo, m.floor() as usize, weight * 0.5, w);
            split(m.ceil() as usize, hi, weight * 0.5, w);
        }
    }
    split(0, n - 1, 1.0, &mut w);
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::AreaLight;

    #[test]
    fn the_weight_line_holds_each_point_once_for_its_weight() {
        for (n1, n2) in [(9, 9), (5, 5), (6, 2), (1, 3), (7, 1)] {
            let (w1, w2) = (grid_weights(n1), grid_weights(n2));
            let order = WeightOrder::new(&w1, &w2);
            let mut seen = vec![0u64; (n1 * n2) as usize];
            let mut at = 0;
            while at < WeightOrder::TOTAL {
                let (point, end) = order.stretch_at(at, 12345);
                assert!(end > at);
                seen[point as usize] += end - at;
                at = end;
            }
            assert_eq!(at, WeightOrder::TOTAL, "{n1}x{n2}");
            for (g, &units) in seen.iter().enumerate() {
                let w = w1[g % n1 as usize] * w2[g / n1 as usize];
                assert_eq!(
                    units as f64 / WeightOrder::TOTAL as f64,
                    w,
                    "{n1}x{n2} point {g}"
                );
            }
        }
    }

    /// Over (u, w) spread evenly on the unit square, every grid point is among the spread
    /// points count / points of the time (up to the spacing's granularity), and each set
    /// holds each index along the longer axis equally often.
    #[test]
    fn spread_points_take_every_point_equally() {
        for (n1, n2) in [(7, 3), (3, 7), (9, 9), (2, 2), (1, 5), (4, 1), (17, 17)] {
            let area = grid_light(n1, n2).area.expect("an area light");
            let count = area.shaded_points();
            let long = n1.max(n2);
            assert!(count >= 6.min(n1 * n2) && count.is_multiple_of(long.min(count)));
            let (u_steps, w_steps) = (200, 2000);
            let mut seen = vec![0u32; (n1 * n2) as usize];
            for i in 0..u_steps {
                for j in 0..w_steps {
                    let u = (f64::from(i) + 0.5) / f64::from(u_steps);
                    let uw = (u, (f64::from(j) + 0.5) / f64::from(w_steps));
                    let mut along = vec![0u32; long as usize];
                    for k in area.spread_points(count, uw) {
                        seen[k as usize] += 1;
                        let index = if n1 >= n2 { k % n1 } else { k / n1 };
                        along[index as usize] += 1;
                    }
                    assert!(along.iter().all(|&a| a == along[0]), "{n1}x{n2}: {along:?}");
                }
            }
            let draws = f64::from(u_steps * w_steps);
            let expected = draws * f64::from(count) / f64::from(n1 * n2);
            // Binning 2000 values of w into n rows is off by up to one value per row.
            let granularity = 2.0 * f64::from(long) / f64::from(w_steps);
            for (k, &n) in seen.iter().enumerate() {
                let off = (f64::from(n) / expected - 1.0).abs();
                assert!(
                    off < granularity,
                    "{n1}x{n2} point {k}: {n} against {expected}"
                );
            }
        }
    }

    /// A jittered n1 x n2 grid along x and z.
    fn grid_area(n1: u32, n2: u32) -> AreaLight {
        AreaLight {
            axis1: DVec3::X,
            axis2: DVec3::Z,
            size1: n1,
            size2: n2,
            adaptive: None,
            jitter: true,
            circular: false,
            orient: false,
        }
    }

    fn with_area(area: AreaLight) -> PreparedLight {
        let mut light = Light::point(DVec3::ZERO, DVec3::ONE);
        light.area = Some(area);
        PreparedLight::new(&light)
    }

    fn grid_light(n1: u32, n2: u32) -> PreparedLight {
        with_area(grid_area(n1, n2))
    }

    #[test]
    fn grid_weights_match_povray() {
        let cases: [(u32, &[f64]); 7] = [
            (1, &[1.0]),
            (2, &[0.5, 0.5]),
            (3, &[0.25, 0.5, 0.25]),
            (4, &[0.25; 4]),
            (5, &[0.125, 0.25, 0.25, 0.25, 0.125]),
            (6, &[0.125, 0.25, 0.125, 0.125, 0.25, 0.125]),
            (7, &[0.125, 0.125, 0.125, 0.25, 0.125, 0.125, 0.125]),
        ];
        for (n, expected) in cases {
            assert_eq!(grid_weights(n), expected, "n = {n}");
        }
        for n in 1..200 {
            let s: f64 = grid_weights(n).iter().sum();
            assert!((s - 1.0).abs() < 1e-12, "n = {n}");
        }
    }

    #[test]
    fn picking_follows_the_weights() {
        let cdf = cumulative(&grid_weights(3));
        assert_eq!(pick(&cdf, 0.0).0, 0);
        assert_eq!(pick(&cdf, 0.2499).0, 0);
        assert_eq!(pick(&cdf, 0.25).0, 1);
        assert_eq!(pick(&cdf, 0.7499).0, 1);
        assert_eq!(pick(&cdf, 0.9999).0, 2);
        let (_, r) = pick(&cdf, 0.5);
        assert!((r - 0.5).abs() < 1e-12);
    }

    /// Where every shadow ray arrives, the adaptive rule tests 3 x 3 points on a 9 x 9
    /// grid at `adaptive 1`, 5 x 5 at 2, the corners alone at 0, a 4 x 3 grid whole at 2,
    /// and 3 of a row of 5 at 1; and finds the light whole.
    #[test]
    fn the_agreeing_rule_tests_the_counted_points() {
        for (n1, n2, adaptive, expected) in [
            (9, 9, 1, 9),
            (9, 9, 2, 25),
            (9, 9, 0, 4),
            (4, 3, 2, 12),
            (1, 5, 1, 3),
        ] {
            let prepared = with_area(AreaLight {
                adaptive: Some(adaptive),
                ..grid_area(n1, n2)
            });
            let area = prepared.area.as_ref().unwrap();
            let filter = area.adaptive_filter(DVec3::Y, DVec3::Y, DVec3::ONE, 7, |_| DVec3::ONE);
            assert_eq!(filter, DVec3::ONE);
            assert_eq!(area.agreeing, expected, "{n1} x {n2} adaptive {adaptive}");
        }
    }

    /// Every point a light places from a shading point, by its grid (jittered or not,
    /// circular or not) or uniformly, lies in the quadrilateral [`PreparedArea::extent`]
    /// gives, and the extent is no more than the grid's half cell and rounding larger.
    #[test]
    fn a_lights_extent_holds_every_point_it_places() {
        let mut uniform = crate::geometry::uniform_stream(0xbb67_ae85_84ca_a73bu64);
        let (a1, a2) = (DVec3::new(3.0, 0.0, 0.0), DVec3::new(0.0, 0.0, 2.0));
        for (size1, size2, jitter, circular) in [
            (9, 9, true, false),
            (4, 3, false, false),
            (1, 5, true, false),
            (7, 7, true, true),
            (1, 1, false, true),
        ] {
            let prepared = with_area(AreaLight {
                axis1: a1,
                axis2: a2,
                jitter,
                circular,
                ..grid_area(size1, size2)
            });
            let area = prepared.area.as_ref().unwrap();
            let frame = area.frame(DVec3::new(1.0, 5.0, -1.0), DVec3::Y);
            for mode in [AreaLightMode::Pov, AreaLightMode::Continuous] {
                let corners = area.extent(&frame, mode);
                let half =
                    |c: DVec3, axis: DVec3| (c - frame.centre).dot(axis) / axis.length_squared();
                let (u, v) = (half(corners[2], a1), half(corners[2], a2));
                for _ in 0..2_000 {
                    let s = (uniform(), uniform());
                    let points = [
                        area.sample_point(&frame, s, mode),
                        area.point_at(
                            &frame,
                            (s.0 * f64::from(size1 * size2)) as u32,
                            (uniform(), uniform()),
                        ),
                    ];
                    for p in points
                        .into_iter()
                        .take(if mode == AreaLightMode::Pov { 2 } else { 1 })
                    {
                        assert!(
                            half(p, a1).abs() <= u && half(p, a2).abs() <= v,
                            "{p} outside {u} {v}"
                        );
                    }
                }
                let most = |n: u32| if n > 1 && jitter { 0.5 + 0.5 / f64::from(n - 1) } else { 0.5 } + 0.002;
                assert!(u <= most(size1) && v <= most(size2), "{u} {v}");
            }
        }
    }

    #[test]
    fn grid_points_span_the_axes() {
        assert_eq!(grid_coordinate(0, 5, None), -0.5);
        assert_eq!(grid_coordinate(4, 5, None), 0.5);
        assert_eq!(grid_coordinate(2, 5, None), 0.0);
        assert_eq!(grid_coordinate(0, 1, Some(0.9)), 0.0);
        assert_eq!(grid_coordinate(0, 5, Some(0.0)), -0.625);
    }
}
