//! Caustics by probabilistic progressive photon mapping (Knaus and Zwicker, "Progressive
//! Photon Mapping: A Probabilistic Approach", 2011).
//!
//! POV-Ray shoots one photon map before it renders and gathers from it everywhere, so its
//! caustic is blurred by the gather radius and noisy by the photon count, and stays so
//! however many samples a pixel takes. penumbra shoots a new, independent set of photons
//! for every sample index (the pass) and gathers pass `j` over a radius `r_j` that shrinks
//! as `r_{j+1}^2 = r_j^2 (j + alpha) / (j + 1)`: each pass's estimate is biased by its
//! radius, but the mean over a pixel's samples converges to the caustic itself, its bias
//! and its noise both falling as the samples grow. Every pass is a pure function of
//! (seed, pass index), so the image is the same for any thread count and any split of the
//! samples.
//!
//! POV-Ray's convention, measured (docs/differences.md, "Photons"): a photon carries the
//! light's colour times the solid angle it stands for, times the square of the length of
//! its path (POV-Ray's lights do not fall off with distance, and neither do its caustics:
//! a plane mirror's caustic equals a second light at the mirror image, to 0.5%), and a
//! surface shows the photons' irradiance times its diffuse colour.

use glam::DVec3;

use crate::geometry::{Aabb, Bvh};

/// Knaus and Zwicker's alpha: the share of photons kept from one pass's radius to the
/// next. 2/3 balances the fall of the bias and of the noise.
const ALPHA: f64 = 2.0 / 3.0;

/// The first pass's radius holds about this many photons where they are densest.
const FIRST_NEIGHBOURS: usize = 8;

/// Photons whose first-radius neighbourhood is measured (spread evenly over the pass).
const RADIUS_PROBES: usize = 200;

/// One photon where it landed, in single precision (the map is large; the gather's
/// precision needs no more).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Photon {
    pub position: [f32; 3],
    /// The light it brings, already scaled by its path length (see the module doc).
    pub power: [f32; 3],
    /// Its direction of travel as it landed.
    pub direction: [f32; 3],
}

impl Photon {
    pub fn new(position: DVec3, power: DVec3, direction: DVec3) -> Photon {
        Photon {
            position: position.as_vec3().to_array(),
            power: power.as_vec3().to_array(),
            direction: direction.as_vec3().to_array(),
        }
    }

    fn position(&self) -> DVec3 {
        glam::Vec3::from_array(self.position).as_dvec3()
    }
}

/// One pass's photons, hashed into a grid of cells twice the gather radius wide, so that a
/// gather looks at the 2 x 2 x 2 cells its sphere can touch.
#[derive(Clone, Debug, Default)]
pub struct PhotonMap {
    photons: Vec<Photon>,
    /// `starts[b]..starts[b + 1]`: the photons of hash bucket b.
    starts: Vec<u32>,
    radius: f64,
    cell: f64,
}

impl PhotonMap {
    pub fn new(photons: Vec<Photon>, radius: f64) -> PhotonMap {
        let cell = 2.0 * radius;
        let buckets = (photons.len() * 2).next_power_of_two().max(1);
        let key = |p: &Photon| bucket(cell_of(p.position(), cell), buckets);
        let mut starts = vec![0u32; buckets + 1];
        for p in &photons {
            starts[key(p) + 1] += 1;
        }
        for b in 0..buckets {
            starts[b + 1] += starts[b];
        }
        let mut next = starts.clone();
        let mut sorted = vec![photons.first().copied().unwrap_or(EMPTY); photons.len()];
        for p in &photons {
            let b = key(p);
            sorted[next[b] as usize] = *p;
            next[b] += 1;
        }
        PhotonMap {
            photons: sorted,
            starts,
            radius,
            cell,
        }
    }

    pub fn len(&self) -> usize {
        self.photons.len()
    }

    pub fn is_empty(&self) -> bool {
        self.photons.is_empty()
    }

    /// The irradiance the photons bring to `p` on a surface facing `n` (photons that
    /// arrive from behind it are not counted): their power within the radius over the
    /// disc's area. A finish's `brilliance` b weighs each photon by cos^(b - 1), its
    /// incidence cosine: POV-Ray shades a photon as a light from its direction, whose
    /// diffuse term is cos^b, while the power per area already holds one cosine (measured:
    /// a floor of brilliance 0.6 under a glass box lit at 18 degrees of elevation sums
    /// to 795.4 in POV-Ray's image, 776.2 without the weight).
    pub fn irradiance(&self, p: DVec3, n: DVec3, brilliance: f64) -> DVec3 {
        if self.photons.is_empty() {
            return DVec3::ZERO;
        }
        let buckets = self.starts.len() - 1;
        let base = cell_of(p, self.cell);
        // The 2 x 2 x 2 block of cells around p: towards the nearer side on each axis.
        let frac = p / self.cell - base.as_dvec3();
        let step = |f: f64| if f < 0.5 { -1 } else { 1 };
        let steps = glam::I64Vec3::new(step(frac.x), step(frac.y), step(frac.z));
        let r2 = (self.radius * self.radius) as f32;
        let (pf, nf) = (p.as_vec3(), n.as_vec3());
        let mut sum = glam::Vec3::ZERO;
        let mut seen = [usize::MAX; 8];
        for k in 0..8 {
            let offset = glam::I64Vec3::new(
                (k & 1) as i64 * steps.x,
                (k >> 1 & 1) as i64 * steps.y,
                (k >> 2 & 1) as i64 * steps.z,
            );
            let b = bucket(base + offset, buckets);
            // Two cells may share a bucket: count its photons once.
            if seen[..k].contains(&b) {
                continue;
            }
            seen[k] = b;
            let range = self.starts[b] as usize..self.starts[b + 1] as usize;
            for photon in &self.photons[range] {
                let q = glam::Vec3::from_array(photon.position);
                let d = glam::Vec3::from_array(photon.direction);
                let cos = -d.dot(nf);
                if (q - pf).length_squared() < r2 && cos > 0.0 {
                    let power = glam::Vec3::from_array(photon.power);
                    sum += if brilliance == 1.0 {
                        power
                    } else {
                        power * cos.powf(brilliance as f32 - 1.0)
                    };
                }
            }
        }
        sum.as_dvec3() / (std::f64::consts::PI * self.radius * self.radius)
    }
}

const EMPTY: Photon = Photon {
    position: [0.0; 3],
    power: [0.0; 3],
    direction: [0.0; 3],
};

fn cell_of(p: DVec3, cell: f64) -> glam::I64Vec3 {
    (p / cell).floor().as_i64vec3()
}

fn bucket(c: glam::I64Vec3, buckets: usize) -> usize {
    let h = (c.x as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15)
        ^ (c.y as u64).wrapping_mul(0xc2b2_ae3d_27d4_eb4f)
        ^ (c.z as u64).wrapping_mul(0x1656_67b1_9e37_79f9);
    ((h ^ (h >> 29)) as usize) & (buckets - 1)
}

/// The gather radius of pass `pass`, from the first pass's.
pub fn pass_radius(first: f64, pass: u32) -> f64 {
    let mut r2 = first * first;
    for i in 1..=pass {
        r2 *= (f64::from(i) + ALPHA) / (f64::from(i) + 1.0);
    }
    r2.sqrt()
}

/// The first pass's radius: the median, over photons spread through the pass, of the
/// distance to their `FIRST_NEIGHBOURS`-th nearest neighbour; `None` with too few photons
/// to tell.
pub fn first_radius(photons: &[Photon]) -> Option<f64> {
    median_kth_distance(photons.len(), |probe| {
        let a = glam::Vec3::from_array(photons[probe].position);
        let d2 = |q: &Photon| (glam::Vec3::from_array(q.position) - a).length_squared();
        photons.iter().map(d2).collect()
    })
}

/// The first pass's radius for beams in media: the median, over probes at the middles of
/// beams spread through the pass, of the distance to their `FIRST_NEIGHBOURS`-th nearest
/// beam, so that the first gather sphere holds about as many beams where they are densest
/// as the surface's holds photons. (Beams cross space where photons dot surfaces: with
/// the surface's radius the media below media_caustic's ball were 2.4 times as noisy at 64
/// samples.) `None` with too few.
pub fn first_beam_radius(beams: &[PhotonBeam]) -> Option<f64> {
    median_kth_distance(beams.len(), |probe| {
        let b = &beams[probe];
        let p = b.origin() + b.direction() * (0.5 * f64::from(b.length));
        beams.iter().map(|q| q.distance_squared(p) as f32).collect()
    })
}

/// Over [`RADIUS_PROBES`] of `n` items spread evenly, the median of the distance to each
/// probe's `FIRST_NEIGHBOURS`-th nearest item (itself included, at 0), from the squared
/// distances `d2(probe)` lists; `None` with too few items or a median of 0.
fn median_kth_distance(n: usize, d2: impl Fn(usize) -> Vec<f32>) -> Option<f64> {
    if n <= FIRST_NEIGHBOURS {
        return None;
    }
    let stride = (n / RADIUS_PROBES).max(1);
    let mut radii: Vec<f64> = (0..n)
        .step_by(stride)
        .map(|probe| {
            let mut d = d2(probe);
            let (_, kth, _) = d.select_nth_unstable_by(FIRST_NEIGHBOURS, f32::total_cmp);
            f64::from(kth.sqrt())
        })
        .collect();
    let mid = radii.len() / 2;
    let (_, median, _) = radii.select_nth_unstable_by(mid, f64::total_cmp);
    (*median > 0.0).then_some(*median)
}

/// One straight stretch of a photon's path through media that scatter, kept whole: the
/// media's share of a caustic is gathered from the length of each beam inside a sphere
/// about the point (the beam estimate of Jarosz et al., "Progressive Photon Beams", 2011,
/// queried at points), which has none of the noise of points strewn along the path.
///
/// A beam carries its photon's light as it starts all along it: POV-Ray dims a photon by
/// the media it crosses from one surface to the next, not along the stretch whose media
/// photons it stores (measured: a mirror's beam through media of extinction 0.2 gave an
/// image 0.310 times the one without extinction, the same at 2 and at 5 units from the
/// mirror; the camera's path through the media and the light's path to the mirror leave
/// 0.563 x 0.549 = 0.309. Dimmed along the beam as well, penumbra gave half that, falling
/// with the distance from 0.69 to 0.42 of the undimmed beam's light.)
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhotonBeam {
    pub origin: [f32; 3],
    /// Unit direction of travel.
    pub direction: [f32; 3],
    pub length: f32,
    /// The light it carries, before its spread over its path's length.
    pub power: [f32; 3],
    /// How far its photon had come when it started, and from which light.
    pub travelled: f32,
    pub light: u32,
}

impl PhotonBeam {
    fn origin(&self) -> DVec3 {
        glam::Vec3::from_array(self.origin).as_dvec3()
    }

    fn direction(&self) -> DVec3 {
        glam::Vec3::from_array(self.direction).as_dvec3()
    }

    /// The light it carries, before its spread.
    pub fn power(&self) -> DVec3 {
        glam::Vec3::from_array(self.power).as_dvec3()
    }

    /// The squared distance from `p` to the nearest point of the beam.
    fn distance_squared(&self, p: DVec3) -> f64 {
        let (o, dir) = (self.origin(), self.direction());
        let along = (p - o).dot(dir).clamp(0.0, f64::from(self.length));
        (o + dir * along - p).length_squared()
    }

    fn bounds(&self, radius: f64) -> Aabb {
        let a = self.origin();
        let b = a + self.direction() * f64::from(self.length);
        let pad = DVec3::splat(radius);
        Aabb::new(a.min(b) - pad, a.max(b) + pad)
    }
}

/// One pass's photon beams, with a tree over their boxes grown by the gather radius, so
/// that a gather visits only beams that may pass within the radius.
#[derive(Debug, Default)]
pub struct BeamMap {
    beams: Vec<PhotonBeam>,
    tree: Option<Bvh>,
    radius: f64,
}

impl BeamMap {
    pub fn new(beams: Vec<PhotonBeam>, radius: f64) -> BeamMap {
        let tree = (!beams.is_empty()).then(|| {
            let bounds: Vec<Aabb> = beams.iter().map(|b| b.bounds(radius)).collect();
            Bvh::build(&bounds)
        });
        BeamMap {
            beams,
            tree,
            radius,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.beams.is_empty()
    }

    /// The light media at `p` scatter along the unit direction `d` per unit length: over
    /// the beams passing within the radius, the light each carries at its nearest point
    /// (`carried`, which applies its spread) times its length inside the sphere, over the
    /// sphere's volume, is the fluence; `scatter(c)` gives the media's scattering
    /// coefficient times their phase function for a beam whose direction towards its light
    /// makes cosine c with `d` (the convention of a light's incidence). This is the light
    /// the beams carry, not POV-Ray's estimate of it, which is brighter by a factor that
    /// depends on its settings and the scene (docs/differences.md, "Photons").
    pub fn in_scattered(
        &self,
        p: DVec3,
        d: DVec3,
        carried: impl Fn(&PhotonBeam, f64) -> DVec3,
        scatter: impl Fn(f64) -> DVec3,
    ) -> DVec3 {
        let Some(tree) = &self.tree else {
            return DVec3::ZERO;
        };
        let r2 = self.radius * self.radius;
        let mut sum = DVec3::ZERO;
        tree.any_containing(p, |i| {
            let beam = &self.beams[i as usize];
            let (o, dir) = (beam.origin(), beam.direction());
            let along = (p - o).dot(dir);
            let h2 = (p - o).length_squared() - along * along;
            if h2 < r2 {
                let half = (r2 - h2).sqrt();
                let length = f64::from(beam.length);
                let chord = (along + half).min(length) - (along - half).max(0.0);
                if chord > 0.0 {
                    let s = along.clamp(0.0, length);
                    sum += carried(beam, s) * chord * scatter(-dir.dot(d));
                }
            }
            false
        });
        sum / (4.0 / 3.0 * std::f64::consts::PI * r2 * self.radius)
    }
}

/// One pass's photons: where they landed on surfaces, and (with `photons { media }`) their
/// beams through media that scatter.
#[derive(Debug, Default)]
pub struct PassMaps {
    pub surface: PhotonMap,
    pub volume: BeamMap,
}

/// The maps of consecutive passes `first..first + maps.len()`.
#[derive(Debug, Default)]
pub struct PhotonMaps {
    pub first: u32,
    pub maps: Vec<PassMaps>,
}

impl PhotonMaps {
    /// The maps a sample of index `index` gathers from.
    pub fn pass(&self, index: u32) -> Option<&PassMaps> {
        index
            .checked_sub(self.first)
            .and_then(|i| self.maps.get(i as usize))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn photon(p: DVec3, power: f64) -> Photon {
        Photon::new(p, DVec3::splat(power), -DVec3::Y)
    }

    /// Brilliance b weighs a photon by cos^(b - 1): one arriving at 60 degrees from the
    /// normal counts 0.5^-0.4 = 1.32 times at b = 0.6 and 0.5 times at b = 2.
    #[test]
    fn brilliance_weighs_photons_by_their_incidence() {
        let slanted = DVec3::new(3f64.sqrt() / 2.0, -0.5, 0.0);
        let map = PhotonMap::new(vec![Photon::new(DVec3::ZERO, DVec3::ONE, slanted)], 0.5);
        let plain = map.irradiance(DVec3::ZERO, DVec3::Y, 1.0).x;
        for (b, factor) in [(0.6, 0.5f64.powf(-0.4)), (2.0, 0.5)] {
            let e = map.irradiance(DVec3::ZERO, DVec3::Y, b).x;
            assert!((e / plain - factor).abs() < 1e-5, "{b}: {}", e / plain);
        }
    }

    #[test]
    fn the_gather_counts_photons_inside_the_radius_from_the_front() {
        let photons = vec![
            photon(DVec3::new(0.1, 0.0, 0.0), 1.0),
            photon(DVec3::new(-0.2, 0.0, 0.3), 2.0),
            // Outside the radius 0.5.
            photon(DVec3::new(0.6, 0.0, 0.0), 4.0),
            // Arriving from below the surface.
            Photon::new(DVec3::ZERO, DVec3::splat(8.0), DVec3::Y),
        ];
        let map = PhotonMap::new(photons, 0.5);
        let e = map.irradiance(DVec3::ZERO, DVec3::Y, 1.0);
        let area = std::f64::consts::PI * 0.25;
        assert!((e.x - 3.0 / area).abs() < 1e-6, "{e}");
    }

    #[test]
    fn the_gather_finds_photons_across_cell_boundaries() {
        // A ring of photons around points near cell corners: each must be found whole.
        for centre in [
            DVec3::ZERO,
            DVec3::splat(0.999),
            DVec3::new(-3.0, 2.0, 1.001),
        ] {
            let photons: Vec<Photon> = (0..64)
                .map(|k| {
                    let a = k as f64 * 0.1;
                    photon(centre + 0.49 * DVec3::new(a.cos(), 0.0, a.sin()), 1.0)
                })
                .collect();
            let map = PhotonMap::new(photons, 0.5);
            let e = map.irradiance(centre, DVec3::Y, 1.0) * std::f64::consts::PI * 0.25;
            assert!((e.x - 64.0).abs() < 1e-3, "{centre}: {e}");
        }
    }

    #[test]
    fn radii_shrink_as_knaus_and_zwicker_ask() {
        assert_eq!(pass_radius(2.0, 0), 2.0);
        let r1 = pass_radius(2.0, 1);
        assert!((r1 * r1 - 4.0 * (1.0 + ALPHA) / 2.0).abs() < 1e-12);
        // r^2 falls as pass^(alpha - 1) for large passes.
        let (a, b) = (pass_radius(1.0, 1000), pass_radius(1.0, 8000));
        let slope = (b * b / (a * a)).ln() / 8f64.ln();
        assert!((slope - (ALPHA - 1.0)).abs() < 0.01, "{slope}");
    }

    /// A 100 x 100 grid of spacing 0.01 in the xz plane, in a shuffled order (7919 is prime
    /// to 10^4), so that evenly strided probes (every 50th) fall in columns 13 and 63,
    /// inside the grid, not on its edge where neighbours are fewer.
    fn shuffled_grid() -> impl Iterator<Item = (f64, f64)> {
        (0..10_000).map(|i| {
            let j = (i * 7919 + 13) % 10_000;
            ((j % 100) as f64 * 0.01, (j / 100) as f64 * 0.01)
        })
    }

    #[test]
    fn the_first_radius_holds_the_asked_neighbours() {
        // The k-th neighbour is about sqrt(k/pi) cells away.
        let photons: Vec<Photon> = shuffled_grid()
            .map(|(x, z)| photon(DVec3::new(x, 0.0, z), 1.0))
            .collect();
        let r = first_radius(&photons).expect("enough photons");
        let expected = 0.01 * (FIRST_NEIGHBOURS as f64 / std::f64::consts::PI).sqrt();
        assert!((r / expected - 1.0).abs() < 0.2, "{r} against {expected}");
        assert_eq!(first_radius(&photons[..FIRST_NEIGHBOURS]), None);
    }

    /// The same grid as beams going up through its points (one unit long): a probe at a
    /// beam's middle has its k-th nearest beam as far as the k-th nearest photon above.
    #[test]
    fn the_first_beam_radius_holds_the_asked_beams() {
        let beams: Vec<PhotonBeam> = shuffled_grid()
            .map(|(x, z)| PhotonBeam {
                origin: [x as f32, -0.5, z as f32],
                direction: [0.0, 1.0, 0.0],
                length: 1.0,
                power: [1.0; 3],
                travelled: 0.0,
                light: 0,
            })
            .collect();
        let r = first_beam_radius(&beams).expect("enough beams");
        let expected = 0.01 * (FIRST_NEIGHBOURS as f64 / std::f64::consts::PI).sqrt();
        assert!((r / expected - 1.0).abs() < 0.2, "{r} against {expected}");
        assert_eq!(first_beam_radius(&beams[..FIRST_NEIGHBOURS]), None);
    }
}
