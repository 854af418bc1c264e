//! POV-Ray's blob: components add a field s (1 - (d / r)^2)^2 within their radius, and the
//! surface is where the sum equals the threshold. Each component lives in a canonical
//! space of radius 1 (a sphere at the origin, or a segment along z from 0 to `length` with
//! hemispherical ends), reached by an affine map, so d^2 is quadratic along a ray and each
//! piece of the field is a quartic in t. The ray is cut at every piece's ends; between
//! cuts the sum is one quartic, solved by the monotone-interval root finder.

use std::cell::Cell;

use glam::{DAffine3, DVec3};

use super::roots::{keeps_sign, roots_in};
use super::{Aabb, Ray};

#[derive(Clone, Debug, PartialEq)]
pub struct BlobData {
    pub threshold: f64,
    pub parts: Vec<BlobPart>,
    pub bounds: Aabb,
    /// Some component has a texture of its own, so the surface's texture is a mix.
    pub textured: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlobPart {
    /// The blob's space to the component's canonical space.
    pub to_local: DAffine3,
    pub strength: f64,
    /// 0 for a sphere; the segment's length in radii for a cylinder.
    pub length: f64,
    /// The component's own material, or `OWN_TEXTURE`: the blob's.
    pub material: u32,
}

/// A component without a texture: it shows the blob's.
pub const OWN_TEXTURE: u32 = u32::MAX;

/// How close to its origin (in the blob's units) a ray ignores the surface it leaves.
const DEPTH_TOLERANCE: f64 = 1e-6;

/// A stretch of the ray where one component contributes the quartic `coef` (highest power
/// first, in u = t - t_ref).
#[derive(Clone, Copy)]
struct Piece {
    start: f64,
    end: f64,
    coef: [f64; 5],
}

/// The pieces along a ray, and their ends as (t, piece * 2 + 1 if it ends there).
type Scratch = (Vec<Piece>, Vec<(f64, u32)>);

thread_local! {
    /// Per-thread buffers, taken and put back, so rays allocate nothing once warm.
    static SCRATCH: Cell<Scratch> = const { Cell::new((Vec::new(), Vec::new())) };
}

impl BlobPart {
    /// The bounds of the component's reach, in the blob's space.
    pub fn bounds(&self) -> Aabb {
        let local = Aabb::new(
            DVec3::new(-1.0, -1.0, -1.0),
            DVec3::new(1.0, 1.0, 1.0 + self.length),
        );
        let forward = self.to_local.inverse();
        let mut out = Aabb::EMPTY;
        for i in 0..8 {
            let c = DVec3::new(
                if i & 1 == 0 { local.min.x } else { local.max.x },
                if i & 2 == 0 { local.min.y } else { local.max.y },
                if i & 4 == 0 { local.min.z } else { local.max.z },
            );
            out = out.grow(forward.transform_point3(c));
        }
        out
    }

    /// The canonical offset from the nearest point of the centre (point or segment).
    #[inline]
    fn offset(&self, p: DVec3) -> DVec3 {
        let q = self.to_local.transform_point3(p);
        q - DVec3::new(0.0, 0.0, q.z.clamp(0.0, self.length))
    }

    /// Pushes the component's pieces along the ray (origin at t_ref already).
    fn pieces(&self, origin: DVec3, direction: DVec3, out: &mut Vec<Piece>) {
        let o = self.to_local.transform_point3(origin);
        let d = self.to_local.transform_vector3(direction);
        let s = self.strength;
        if self.length == 0.0 {
            sphere_piece(o, d, s, f64::NEG_INFINITY, f64::INFINITY, out);
            return;
        }
        // The slab 0 <= z <= length along u, and the parts of the line before and after it.
        let (z0, z1) = if d.z != 0.0 {
            let a = -o.z / d.z;
            let b = (self.length - o.z) / d.z;
            (a.min(b), a.max(b))
        } else if o.z >= 0.0 && o.z <= self.length {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            // Wholly beside the segment: one end cap covers the whole line.
            let end = if o.z < 0.0 { 0.0 } else { self.length };
            let oc = o - DVec3::new(0.0, 0.0, end);
            sphere_piece(oc, d, s, f64::NEG_INFINITY, f64::INFINITY, out);
            return;
        };
        // Radial distance in the slab.
        let radial_o = DVec3::new(o.x, o.y, 0.0);
        let radial_d = DVec3::new(d.x, d.y, 0.0);
        sphere_piece(radial_o, radial_d, s, z0, z1, out);
        if z0.is_finite() {
            // Before the slab the ray is beyond the end it enters by, after it beyond the
            // other one.
            let (first, second) = if d.z > 0.0 {
                (0.0, self.length)
            } else {
                (self.length, 0.0)
            };
            sphere_piece(o - DVec3::Z * first, d, s, f64::NEG_INFINITY, z0, out);
            sphere_piece(o - DVec3::Z * second, d, s, z1, f64::INFINITY, out);
        }
    }
}

/// Where the whole line meets a box, slightly enlarged so rounding never cuts the surface.
fn line_span(b: &Aabb, ray: &Ray) -> Option<(f64, f64)> {
    let pad = DVec3::splat(1e-9 * (b.max - b.min).max_element());
    let inv = ray.direction.recip();
    let t1 = (b.min - pad - ray.origin) * inv;
    let t2 = (b.max + pad - ray.origin) * inv;
    let (near, far) = (t1.min(t2).max_element(), t1.max(t2).min_element());
    (near <= far && near.is_finite() && far.is_finite()).then_some((near, far))
}

/// The piece of s (1 - |o + u d|^2)^2 where |o + u d| < 1, within [lo, hi].
fn sphere_piece(o: DVec3, d: DVec3, s: f64, lo: f64, hi: f64, out: &mut Vec<Piece>) {
    let a = d.length_squared();
    let b = 2.0 * o.dot(d);
    let c = o.length_squared() - 1.0;
    let (start, end) = if a == 0.0 {
        if c >= 0.0 {
            return;
        }
        (lo, hi)
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc <= 0.0 {
            return;
        }
        let q = -0.5 * (b + b.signum() * disc.sqrt());
        let (r0, r1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
        (r0.min(r1).max(lo), r0.max(r1).min(hi))
    };
    // Also drops NaN ends, which would unbalance the sweep's count.
    if start.partial_cmp(&end) != Some(std::cmp::Ordering::Less) {
        return;
    }
    // w = 1 - |o + u d|^2 = -(a u^2 + b u + c); s w^2.
    let (al, be, ga) = (-a, -b, -c);
    out.push(Piece {
        start,
        end,
        coef: [
            s * al * al,
            s * 2.0 * al * be,
            s * (be * be + 2.0 * al * ga),
            s * 2.0 * be * ga,
            s * ga * ga,
        ],
    });
}

impl BlobData {
    /// The blob of `parts`, bounded by the reach of its positive components (a negative
    /// one only takes away).
    pub fn new(threshold: f64, parts: Vec<BlobPart>) -> BlobData {
        let bounds = parts
            .iter()
            .filter(|p| p.strength > 0.0)
            .fold(Aabb::EMPTY, |b, p| b.union(&p.bounds()));
        BlobData {
            threshold,
            textured: parts.iter().any(|p| p.material != OWN_TEXTURE),
            parts,
            bounds,
        }
    }

    /// The summed field at a point of the blob's space.
    pub fn field(&self, p: DVec3) -> f64 {
        self.parts
            .iter()
            .map(|part| {
                let w = 1.0 - part.offset(p).length_squared();
                if w > 0.0 { part.strength * w * w } else { 0.0 }
            })
            .sum()
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.field(p) > self.threshold
    }

    /// The materials shown at a point and their weights: each component reaching it, by
    /// the magnitude of the field it adds (POV-Ray's mix, measured on two, three and four
    /// components with a negative one); `own` for a component without a texture.
    pub fn texture_weights(&self, p: DVec3, own: u32) -> impl Iterator<Item = (u32, f64)> + '_ {
        self.parts.iter().filter_map(move |part| {
            let w = 1.0 - part.offset(p).length_squared();
            let material = if part.material == OWN_TEXTURE {
                own
            } else {
                part.material
            };
            (w > 0.0).then(|| (material, (part.strength * w * w).abs()))
        })
    }

    /// Outward normal: minus the field's gradient.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let mut n = DVec3::ZERO;
        for part in &self.parts {
            let r = part.offset(p);
            let w = 1.0 - r.length_squared();
            if w > 0.0 {
                // d/dq of s w^2 is -4 s w r; back to the blob's space by the transpose.
                let g = r * (4.0 * part.strength * w);
                n += part.to_local.matrix3.transpose() * g;
            }
        }
        n
    }

    /// Calls `f` with every crossing along the line, in increasing order, until it returns
    /// false.
    pub fn each_hit(&self, ray: &Ray, mut f: impl FnMut(f64) -> bool) {
        let Some((enter, exit)) = line_span(&self.bounds, ray) else {
            return;
        };
        // Measure t from the middle of the bounds' span, which keeps the quartics'
        // coefficients small however far the ray starts.
        let t_ref = 0.5 * (enter + exit);
        let origin = ray.at(t_ref);
        let (mut pieces, mut events) = SCRATCH.take();
        pieces.clear();
        events.clear();
        for part in &self.parts {
            part.pieces(origin, ray.direction, &mut pieces);
        }
        for (i, piece) in pieces.iter().enumerate() {
            events.push((piece.start, i as u32 * 2));
            events.push((piece.end, i as u32 * 2 + 1));
        }
        events.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        let tolerance = DEPTH_TOLERANCE / ray.direction.length().max(1e-300);
        let mut sum = [0.0; 5];
        let mut active = 0usize;
        let mut last_root = f64::NEG_INFINITY;
        let mut from = f64::NEG_INFINITY;
        'sweep: for &(u, code) in &events {
            let mut poly = sum;
            poly[4] -= self.threshold;
            // Half of a ray's intervals hold no root: those whose polynomial keeps its
            // sign are passed over without the search (objects/blob.pov -5.7% instructions).
            if active > 0 && u > from && !keeps_sign(&poly, from, u) {
                for &r in roots_in(&poly, from, u).as_slice() {
                    let t = r + t_ref;
                    if r - last_root <= 1e-12 * (r.abs() + 1.0) {
                        continue;
                    }
                    last_root = r;
                    if t.abs() > tolerance && !f(t) {
                        break 'sweep;
                    }
                }
            }
            from = u;
            let piece = &pieces[(code / 2) as usize];
            if code % 2 == 0 {
                active += 1;
                for (s, c) in sum.iter_mut().zip(piece.coef) {
                    *s += c;
                }
            } else {
                active -= 1;
                if active == 0 {
                    sum = [0.0; 5];
                } else {
                    for (s, c) in sum.iter_mut().zip(piece.coef) {
                        *s -= c;
                    }
                }
            }
        }
        SCRATCH.set((pieces, events));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere_part(center: DVec3, radius: f64, strength: f64) -> BlobPart {
        BlobPart {
            to_local: DAffine3::from_scale(DVec3::splat(1.0 / radius))
                * DAffine3::from_translation(-center),
            strength,
            length: 0.0,
            material: OWN_TEXTURE,
        }
    }

    fn blob(threshold: f64, parts: Vec<BlobPart>) -> BlobData {
        BlobData::new(threshold, parts)
    }

    fn hits(b: &BlobData, ray: &Ray) -> Vec<f64> {
        let mut out = Vec::new();
        b.each_hit(ray, |t| {
            out.push(t);
            true
        });
        out
    }

    #[test]
    fn one_sphere_component() {
        // s (1 - d^2)^2 = t at d^2 = 1 - sqrt(t / s): s = 1, t = 0.25 gives d = sqrt(0.5).
        let b = blob(0.25, vec![sphere_part(DVec3::ZERO, 1.0, 1.0)]);
        let h = hits(&b, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z));
        let r = 0.5f64.sqrt();
        assert_eq!(h.len(), 2, "{h:?}");
        assert!((h[0] - (5.0 - r)).abs() < 1e-9 && (h[1] - (5.0 + r)).abs() < 1e-9);
        assert!(b.inside(DVec3::new(0.0, 0.6, 0.0)) && !b.inside(DVec3::new(0.0, 0.75, 0.0)));
        let n = b.normal(DVec3::new(0.0, 0.0, -r));
        assert!(n.normalize().abs_diff_eq(-DVec3::Z, 1e-12), "{n}");
        // Far away and with a long direction.
        let h = hits(&b, &Ray::new(DVec3::new(0.0, 0.0, -1e5), DVec3::Z * 4.0));
        assert!((h[0] * 4.0 - (1e5 - r)).abs() < 1e-6, "{h:?}");
    }

    #[test]
    fn grazing_rays_hit_or_miss_correctly() {
        let b = blob(0.25, vec![sphere_part(DVec3::ZERO, 1.0, 1.0)]);
        let r = 0.5f64.sqrt();
        for k in 2..=7 {
            let e = 10f64.powi(-k);
            let inside = Ray::new(DVec3::new(r - e, 0.0, -5.0), DVec3::Z);
            let outside = Ray::new(DVec3::new(r + e, 0.0, -5.0), DVec3::Z);
            assert_eq!(hits(&b, &inside).len(), 2, "k={k}");
            assert!(hits(&b, &outside).is_empty(), "k={k}");
        }
    }

    #[test]
    fn two_spheres_merge_and_a_negative_one_cuts() {
        // Two spheres of radius 1 at x = -0.5 and 0.5, threshold 0.5: at the origin each
        // gives (1 - 0.25)^2 = 0.5625, so the middle is joined.
        let parts = vec![
            sphere_part(DVec3::new(-0.5, 0.0, 0.0), 1.0, 1.0),
            sphere_part(DVec3::new(0.5, 0.0, 0.0), 1.0, 1.0),
        ];
        let b = blob(0.5, parts.clone());
        assert!(b.inside(DVec3::ZERO));
        let h = hits(&b, &Ray::new(DVec3::new(0.0, -5.0, 0.0), DVec3::Y));
        assert_eq!(h.len(), 2, "{h:?}");
        // The crossing on the y axis: 2 (1 - 0.25 - y^2)^2 = 0.5, y^2 = 0.25.
        assert!((h[0] - 4.5).abs() < 1e-9, "{h:?}");
        // A strong negative component at the origin hollows it.
        let mut cut = parts;
        cut.push(sphere_part(DVec3::ZERO, 0.5, -4.0));
        let b = blob(0.5, cut);
        assert!(!b.inside(DVec3::ZERO));
        let h = hits(&b, &Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X));
        assert_eq!(h.len(), 4, "{h:?}");
    }

    #[test]
    fn a_cylinder_component_has_round_ends() {
        // Along z from 0 to 2 radii (radius 1), strength 1, threshold 0.25: the surface
        // is sqrt(0.5) from the segment.
        let b = blob(
            0.25,
            vec![BlobPart {
                to_local: DAffine3::IDENTITY,
                strength: 1.0,
                length: 2.0,
                material: OWN_TEXTURE,
            }],
        );
        let r = 0.5f64.sqrt();
        let h = hits(&b, &Ray::new(DVec3::new(-5.0, 0.0, 1.0), DVec3::X));
        assert!((h[0] - (5.0 - r)).abs() < 1e-9, "{h:?}");
        // Along the axis: the hemispheres.
        let h = hits(&b, &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z));
        assert!((h[0] - (5.0 - r)).abs() < 1e-9 && (h[1] - (7.0 + r)).abs() < 1e-9);
        // Slanted through an end cap.
        let d = DVec3::new(1.0, 0.0, 1.0).normalize();
        let h = hits(&b, &Ray::new(DVec3::new(-0.3, 0.0, 2.2) - 5.0 * d, d));
        let p = Ray::new(DVec3::new(-0.3, 0.0, 2.2) - 5.0 * d, d).at(h[0]);
        assert!((b.field(p) - 0.25).abs() < 1e-9, "{p}");
        assert!(b.inside(DVec3::new(0.0, 0.0, 2.5)) && !b.inside(DVec3::new(0.0, 0.0, 2.8)));
    }

    #[test]
    fn texture_weights_are_each_components_field_magnitude() {
        let mut red = sphere_part(DVec3::new(-0.6, 0.0, 0.0), 1.0, 1.0);
        red.material = 3;
        let untextured = sphere_part(DVec3::new(0.6, 0.0, 0.0), 1.0, 2.0);
        let mut negative = sphere_part(DVec3::new(0.0, 0.5, 0.0), 1.0, -0.5);
        negative.material = 5;
        let far = sphere_part(DVec3::new(9.0, 0.0, 0.0), 1.0, 1.0);
        let b = blob(0.3, vec![red, untextured, negative, far]);
        assert!(b.textured);
        let w: Vec<(u32, f64)> = b.texture_weights(DVec3::ZERO, 7).collect();
        // (1 - 0.36)^2 = 0.4096 for both sides; (1 - 0.25)^2 = 0.5625; the far one is out
        // of reach.
        let expected = [(3, 0.4096), (7, 2.0 * 0.4096), (5, 0.5 * 0.5625)];
        assert_eq!(w.len(), expected.len());
        for ((m, x), (em, ex)) in w.iter().zip(expected) {
            assert_eq!(*m, em);
            assert!((x - ex).abs() < 1e-12, "{x} vs {ex}");
        }
        assert!(!blob(0.3, vec![far]).textured);
    }
}
