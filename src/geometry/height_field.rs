//! POV-Ray's height field: a grid of heights over the unit square of x and z, two
//! triangles per cell. It keeps only the heights (a 512 x 512 image is a million bytes, not
//! half a million triangles) and walks the cells a ray crosses, tile by tile, skipping tiles
//! whose height range the ray passes above or below.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use glam::{DVec2, DVec3};

use super::{Aabb, Ray};

/// Cells per side of a tile with its own height range.
const TILE: usize = 8;

#[derive(Clone, Debug)]
pub struct HeightFieldData {
    /// Grid points along x and z (at least 2 each).
    nx: usize,
    nz: usize,
    /// Row by row along x: the point (ix, iz) at `iz * nx + ix`, at x = ix / (nx - 1),
    /// z = iz / (nz - 1).
    heights: Arc<Vec<f32>>,
    /// Lowest and highest height of each tile's points, tile rows along x.
    tiles: Vec<[f32; 2]>,
    tiles_x: usize,
    tiles_z: usize,
    max_height: f64,
    water_level: f64,
    smooth: bool,
    /// With `smooth`, the grid points' normals as POV-Ray stores them, row by row as
    /// `heights`: each shading point interpolates four, and computing them afresh there
    /// took 12% of advanced/crater's render.
    normals: NormalCache,
}

/// Grid points' quantised normals (`quantised_normal`), each computed the first time a
/// shading point needs it (a small render of a large field computes few) and kept, packed
/// as three 16-bit fields under `COMPUTED`, so threads share them without a lock: two
/// threads that compute the same point store the same bits.
#[derive(Debug, Default)]
struct NormalCache(Box<[AtomicU64]>);

const COMPUTED: u64 = 1 << 63;

impl NormalCache {
    fn new(points: usize) -> NormalCache {
        NormalCache((0..points).map(|_| AtomicU64::new(0)).collect())
    }

    fn get(&self, i: usize, compute: impl FnOnce() -> [i16; 3]) -> [i16; 3] {
        let slot = &self.0[i];
        let mut bits = slot.load(Ordering::Relaxed);
        if bits & COMPUTED == 0 {
            let q = compute();
            bits = COMPUTED
                | q.iter()
                    .rev()
                    .fold(0, |b, &c| b << 16 | u64::from(c as u16));
            slot.store(bits, Ordering::Relaxed);
        }
        [
            bits as u16 as i16,
            (bits >> 16) as u16 as i16,
            (bits >> 32) as u16 as i16,
        ]
    }
}

impl Clone for NormalCache {
    fn clone(&self) -> NormalCache {
        NormalCache(
            self.0
                .iter()
                .map(|a| AtomicU64::new(a.load(Ordering::Relaxed)))
                .collect(),
        )
    }
}

/// A ray in grid units: x and z scaled to cell units; t is unchanged.
struct GridRay {
    o: DVec3,
    d: DVec3,
}

impl HeightFieldData {
    /// `None` when the grid has fewer than 2 x 2 points or the heights do not fill it.
    pub fn new(
        nx: usize,
        nz: usize,
        heights: Arc<Vec<f32>>,
        smooth: bool,
        water_level: f64,
    ) -> Option<HeightFieldData> {
        if nx < 2 || nz < 2 || heights.len() != nx * nz {
            return None;
        }
        let tiles_x = (nx - 1).div_ceil(TILE);
        let tiles_z = (nz - 1).div_ceil(TILE);
        let mut tiles = vec![[f32::INFINITY, f32::NEG_INFINITY]; tiles_x * tiles_z];
        for iz in 0..nz {
            for ix in 0..nx {
                let h = heights[iz * nx + ix];
                // A point on a tile's edge belongs to the tiles either side.
                for tz in tile_span(iz, tiles_z) {
                    for tx in tile_span(ix, tiles_x) {
                        let t = &mut tiles[tz * tiles_x + tx];
                        t[0] = t[0].min(h);
                        t[1] = t[1].max(h);
                    }
                }
            }
        }
        let max_height = heights.iter().fold(0.0f32, |a, &h| a.max(h)) as f64;
        Some(HeightFieldData {
            nx,
            nz,
            heights,
            tiles,
            tiles_x,
            tiles_z,
            max_height,
            water_level,
            smooth,
            normals: NormalCache::new(if smooth { nx * nz } else { 0 }),
        })
    }

    /// The heights' box, from y = 0, which the inside reaches down to.
    pub fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::ZERO, DVec3::new(1.0, self.max_height, 1.0))
    }

    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of::<HeightFieldData>()
            + self.heights.len() * 4
            + self.tiles.len() * 8
            + self.normals.0.len() * 8
    }

    fn cells(&self) -> (usize, usize) {
        (self.nx - 1, self.nz - 1)
    }

    #[inline]
    fn h(&self, ix: usize, iz: usize) -> f64 {
        self.heights[iz * self.nx + ix] as f64
    }

    fn grid_ray(&self, ray: &Ray) -> GridRay {
        let (sx, sz) = self.cells();
        let s = DVec3::new(sx as f64, 1.0, sz as f64);
        GridRay {
            o: ray.origin * s,
            d: ray.direction * s,
        }
    }

    /// The part of (0, t_max) where the ray is over the grid within its height range.
    fn clip(&self, r: &GridRay, t_max: f64) -> Option<(f64, f64)> {
        let (sx, sz) = self.cells();
        let pad = 1e-9 * (1.0 + self.max_height);
        let lo = DVec3::new(-pad, self.water_level.max(0.0) - pad, -pad);
        let hi = DVec3::new(sx as f64 + pad, self.max_height + pad, sz as f64 + pad);
        let (mut t0, mut t1) = (0.0f64, t_max);
        for a in 0..3 {
            let (o, d) = (r.o[a], r.d[a]);
            if d == 0.0 {
                if o < lo[a] || o > hi[a] {
                    return None;
                }
                continue;
            }
            let (ta, tb) = ((lo[a] - o) / d, (hi[a] - o) / d);
            t0 = t0.max(ta.min(tb));
            t1 = t1.min(ta.max(tb));
        }
        (t0 <= t1).then_some((t0, t1))
    }

    /// Visits the cells the ray crosses within (t0, t1), nearest first, skipping tiles it
    /// passes above, below or under the water; stops when `visit` returns false.
    fn walk_cells(
        &self,
        r: &GridRay,
        t0: f64,
        t1: f64,
        mut visit: impl FnMut(usize, usize) -> bool,
    ) {
        let (o, d) = (DVec2::new(r.o.x, r.o.z), DVec2::new(r.d.x, r.d.z));
        let tiles = (self.tiles_x, self.tiles_z);
        walk(o, d, t0, t1, TILE as f64, tiles, |tx, tz, ta, tb| {
            let [lo, hi] = self.tiles[tz * self.tiles_x + tx];
            let (ya, yb) = (r.o.y + r.d.y * ta, r.o.y + r.d.y * tb);
            let pad = 1e-9 * (1.0 + self.max_height);
            let (ylo, yhi) = (ya.min(yb) - pad, ya.max(yb) + pad);
            if yhi < lo as f64 || ylo > hi as f64 || yhi < self.water_level {
                return true;
            }
            walk(o, d, ta, tb, 1.0, self.cells(), |cx, cz, ca, cb| {
                !self.may_cross_cell(r, cx, cz, (ca, cb), pad) || visit(cx, cz)
            })
        });
    }

    /// Whether the ray's height over the part (ta, tb) of its path above the cell reaches
    /// the cell's range of corner heights: both triangles lie within that range, so a ray
    /// wholly above or below it crosses neither, and most cells a ray passes over are
    /// skipped before their two triangle tests.
    #[inline]
    fn may_cross_cell(&self, r: &GridRay, cx: usize, cz: usize, t: (f64, f64), pad: f64) -> bool {
        let (ya, yb) = (r.o.y + r.d.y * t.0, r.o.y + r.d.y * t.1);
        let row = cz * self.nx + cx;
        let hs = &self.heights[row..row + self.nx + 2];
        let (a, b, c, e) = (hs[0], hs[1], hs[self.nx], hs[self.nx + 1]);
        let lo = a.min(b).min(c.min(e)) as f64;
        let hi = a.max(b).max(c.max(e)) as f64;
        ya.min(yb) - pad <= hi && ya.max(yb) + pad >= lo
    }

    /// The corners of a cell's triangle `k` in grid units: 0 is the one at the cell's
    /// (x, z) corner, 1 the one at its (x + 1, z + 1) corner; the diagonal runs from
    /// (x + 1, z) to (x, z + 1), as POV-Ray splits cells (measured).
    fn triangle(&self, cx: usize, cz: usize, k: u32) -> [DVec3; 3] {
        let p = |ix: usize, iz: usize| DVec3::new(ix as f64, self.h(ix, iz), iz as f64);
        if k == 0 {
            [p(cx, cz), p(cx + 1, cz), p(cx, cz + 1)]
        } else {
            [p(cx + 1, cz + 1), p(cx, cz + 1), p(cx + 1, cz)]
        }
    }

    /// The cell's crossings above the water, with their parts.
    #[inline]
    fn cell_hits(&self, r: &GridRay, cx: usize, cz: usize, mut f: impl FnMut(f64, u32)) {
        let cell = (cz * (self.nx - 1) + cx) as u32;
        for k in 0..2 {
            let [a, b, c] = self.triangle(cx, cz, k);
            if let Some(t) = triangle_t(r, a, b, c)
                && r.o.y + r.d.y * t >= self.water_level
            {
                f(t, cell * 2 + k);
            }
        }
    }

    /// The nearest hit in (0, t_max) and its part (cell and triangle).
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<(f64, u32)> {
        let r = self.grid_ray(ray);
        let (t0, t1) = self.clip(&r, t_max)?;
        let mut best: Option<(f64, u32)> = None;
        self.walk_cells(&r, t0, t1, |cx, cz| {
            self.cell_hits(&r, cx, cz, |t, part| {
                if t > 0.0 && t < t_max && best.is_none_or(|b| t < b.0) {
                    best = Some((t, part));
                }
            });
            best.is_none()
        });
        best
    }

    /// Every crossing ahead of the ray's origin, with its part.
    pub fn each_hit(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        let r = self.grid_ray(ray);
        let Some((t0, t1)) = self.clip(&r, f64::INFINITY) else {
            return;
        };
        self.walk_cells(&r, t0, t1, |cx, cz| {
            self.cell_hits(&r, cx, cz, |t, part| {
                if t > 0.0 {
                    f(t, part);
                }
            });
            true
        });
    }

    fn decode(&self, part: u32) -> (usize, usize, u32) {
        let cell = (part / 2) as usize;
        let sx = self.nx - 1;
        (
            (cell % sx).min(sx - 1),
            (cell / sx).min(self.nz - 2),
            part % 2,
        )
    }

    /// From grid units back to the object's: x and z stretch by the cell counts.
    fn to_object_normal(&self, n: DVec3) -> DVec3 {
        let (sx, sz) = self.cells();
        DVec3::new(n.x * sx as f64, n.y, n.z * sz as f64)
    }

    /// The triangle's upward normal.
    pub fn normal(&self, part: u32) -> DVec3 {
        let (cx, cz, k) = self.decode(part);
        let [a, b, c] = self.triangle(cx, cz, k);
        let n = (c - a).cross(b - a);
        self.to_object_normal(if n.y < 0.0 { -n } else { n })
    }

    /// With `smooth`, the grid points' normals interpolated bilinearly across the cell, as
    /// POV-Ray does (measured inside the cells of a 5 x 5 function field: worst slope
    /// difference 0.015, against 0.07 for interpolation over the triangle).
    pub fn shading_normal(&self, part: u32, p: DVec3) -> DVec3 {
        if !self.smooth {
            return self.normal(part);
        }
        let (cx, cz, _) = self.decode(part);
        let (sx, sz) = self.cells();
        let (fx, fz) = (p.x * sx as f64 - cx as f64, p.z * sz as f64 - cz as f64);
        let n = |ix, iz| self.point_normal(ix, iz);
        let s = n(cx, cz) * ((1.0 - fx) * (1.0 - fz))
            + n(cx + 1, cz) * (fx * (1.0 - fz))
            + n(cx, cz + 1) * ((1.0 - fx) * fz)
            + n(cx + 1, cz + 1) * (fx * fz);
        self.to_object_normal(s)
    }

    /// A grid point's normal in grid units, from its stored quantised form.
    fn point_normal(&self, ix: usize, iz: usize) -> DVec3 {
        let q = self
            .normals
            .get(iz * self.nx + ix, || self.quantised_normal(ix, iz));
        let [x, y, z] = q.map(f64::from);
        // Back from height units to grid units (y scales as the height does).
        DVec3::new(x, y * HEIGHT_UNITS, z).normalize_or(DVec3::Y)
    }

    /// A grid point's normal as POV-Ray computes and stores it: in its 16-bit height
    /// units (heights 0 to 65535, one unit per grid step), the mean of the unit normals of
    /// the quadrants around the point (fewer on the edges), each component then truncated
    /// to a multiple of 1/32767, kept as that multiple. On steep fields that leaves few normals
    /// (slopes of 1, 2/3, 1/2, ... of the cell's width over its height), which POV-Ray
    /// shows. Measured at the grid points of 5 x 5 and 33 x 25 function fields
    /// (scripts/hf_smooth_normals.py): worst slope difference 0.001, where plain central
    /// differences are up to 0.29 off; advanced/crater.pov's 16-bit PNG: sqrt(B) 0.0071 ->
    /// 0.0013.
    fn quantised_normal(&self, ix: usize, iz: usize) -> [i16; 3] {
        let h0 = self.h(ix, iz) * HEIGHT_UNITS;
        let step = |jx: usize, jz: usize, x: f64, z: f64| {
            DVec3::new(x, self.h(jx, jz) * HEIGHT_UNITS - h0, z)
        };
        let east = (ix + 1 < self.nx).then(|| step(ix + 1, iz, 1.0, 0.0));
        let west = (ix > 0).then(|| step(ix - 1, iz, -1.0, 0.0));
        let north = (iz + 1 < self.nz).then(|| step(ix, iz + 1, 0.0, 1.0));
        let south = (iz > 0).then(|| step(ix, iz - 1, 0.0, -1.0));
        let mut sum = DVec3::ZERO;
        for (a, b) in [(east, north), (north, west), (west, south), (south, east)] {
            if let (Some(a), Some(b)) = (a, b) {
                let c = b.cross(a);
                sum += if c.y < 0.0 { -c } else { c }.normalize();
            }
        }
        let q = (sum.normalize_or(DVec3::Y) * NORMAL_UNITS).trunc();
        // |q| <= NORMAL_UNITS = i16::MAX: the casts are exact.
        [q.x as i16, q.y as i16, q.z as i16]
    }

    /// The surface's height over an object-space (x, z) in the unit square.
    fn height_at(&self, x: f64, z: f64) -> f64 {
        let (sx, sz) = self.cells();
        let (gx, gz) = (x * sx as f64, z * sz as f64);
        let cx = (gx.floor() as usize).min(sx - 1);
        let cz = (gz.floor() as usize).min(sz - 1);
        let (fx, fz) = (gx - cx as f64, gz - cz as f64);
        let h = |dx, dz| self.h(cx + dx, cz + dz);
        if fx + fz <= 1.0 {
            h(0, 0) + fx * (h(1, 0) - h(0, 0)) + fz * (h(0, 1) - h(0, 0))
        } else {
            h(1, 1) + (1.0 - fx) * (h(0, 1) - h(1, 1)) + (1.0 - fz) * (h(1, 0) - h(1, 1))
        }
    }

    /// Under the surface and above y = 0 over the unit square, whatever the water level
    /// (measured with boxes intersected with a height field: one below y = 0 vanishes, one
    /// under the water shows).
    pub fn inside(&self, p: DVec3) -> bool {
        (0.0..=1.0).contains(&p.x)
            && (0.0..=1.0).contains(&p.z)
            && p.y >= 0.0
            && p.y < self.height_at(p.x, p.z)
    }
}

/// The height units of POV-Ray's stored fields, and of its stored normals' components.
const HEIGHT_UNITS: f64 = 65535.0;
const NORMAL_UNITS: f64 = 32767.0;

/// The tiles a grid point along one axis belongs to.
fn tile_span(i: usize, tiles: usize) -> std::ops::RangeInclusive<usize> {
    let hi = (i / TILE).min(tiles - 1);
    let lo = if i.is_multiple_of(TILE) && i > 0 {
        i / TILE - 1
    } else {
        hi
    };
    lo.min(hi)..=hi
}

/// Möller-Trumbore's distance, edges included.
#[inline]
fn triangle_t(r: &GridRay, a: DVec3, b: DVec3, c: DVec3) -> Option<f64> {
    let (e1, e2) = (b - a, c - a);
    let p = r.d.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let s = r.o - a;
    let u = s.dot(p) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let v = r.d.dot(q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    Some(e2.dot(q) * inv)
}

/// A 2-D DDA: the squares of side `size` (`n` of them per axis from the origin) that the
/// line `o + t d` crosses for t in (t0, t1), in order, each with the part of (t0, t1) over
/// it, until `visit` returns false; returns whether it ran to the end.
fn walk(
    o: DVec2,
    d: DVec2,
    t0: f64,
    t1: f64,
    size: f64,
    n: (usize, usize),
    mut visit: impl FnMut(usize, usize, f64, f64) -> bool,
) -> bool {
    let start = o + d * t0;
    let cell = |v: f64, n: usize| ((v / size).floor().max(0.0) as usize).min(n - 1);
    let (mut i, mut j) = (cell(start.x, n.0), cell(start.y, n.1));
    // Where the line next crosses a column and a row boundary, and how far apart they are.
    let next = |k: usize, o: f64, d: f64| {
        if d > 0.0 {
            ((k + 1) as f64 * size - o) / d
        } else if d < 0.0 {
            (k as f64 * size - o) / d
        } else {
            f64::INFINITY
        }
    };
    let (mut nx, mut nz) = (next(i, o.x, d.x), next(j, o.y, d.y));
    let (dx, dz) = (size / d.x.abs(), size / d.y.abs());
    let mut t = t0;
    loop {
        let t_out = nx.min(nz).min(t1);
        if !visit(i, j, t, t_out) {
            return false;
        }
        if t_out >= t1 {
            return true;
        }
        t = t_out;
        if nx <= nz {
            if d.x > 0.0 && i + 1 < n.0 {
                i += 1;
            } else if d.x < 0.0 && i > 0 {
                i -= 1;
            } else {
                return true;
            }
            nx += dx;
        } else {
            if d.y > 0.0 && j + 1 < n.1 {
                j += 1;
            } else if d.y < 0.0 && j > 0 {
                j -= 1;
            } else {
                return true;
            }
            nz += dz;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pyramid-ish grid of `n x n` points, highest in the middle.
    fn field(n: usize) -> HeightFieldData {
        let mut h = Vec::new();
        for iz in 0..n {
            for ix in 0..n {
                let c = (n - 1) as f64 / 2.0;
                let d = (ix as f64 - c).abs().max((iz as f64 - c).abs()) / c;
                h.push((1.0 - d) as f32 * 0.5);
            }
        }
        HeightFieldData::new(n, n, Arc::new(h), false, 0.0).unwrap()
    }

    /// The nearest crossing by brute force over every cell.
    fn brute(hf: &HeightFieldData, ray: &Ray) -> Option<f64> {
        let r = hf.grid_ray(ray);
        let mut best: Option<f64> = None;
        for cz in 0..hf.nz - 1 {
            for cx in 0..hf.nx - 1 {
                hf.cell_hits(&r, cx, cz, |t, _| {
                    if t > 0.0 && best.is_none_or(|b| t < b) {
                        best = Some(t);
                    }
                });
            }
        }
        best
    }

    #[test]
    fn the_walk_finds_what_testing_every_cell_finds() {
        let hf = field(37);
        let mut state = 12345u64;
        let mut next = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..2000 {
            let o = DVec3::new(next() * 3.0 - 1.0, next() * 2.0, next() * 3.0 - 1.0);
            let target = DVec3::new(next(), next() * 0.5, next());
            let ray = Ray::new(o, target - o);
            let got = hf.hit(&ray, f64::INFINITY).map(|h| h.0);
            let want = brute(&hf, &ray);
            match (got, want) {
                (Some(a), Some(b)) => assert!((a - b).abs() < 1e-9, "{a} {b}"),
                (a, b) => assert_eq!(a, b, "{ray:?}"),
            }
        }
        // Straight down onto the apex.
        let t = hf.hit(&Ray::new(DVec3::new(0.5, 2.0, 0.5), -DVec3::Y), 10.0);
        assert!((t.unwrap().0 - 1.5).abs() < 1e-9);
    }

    /// The kept normals are those computed afresh, whichever points are asked for first
    /// and however often: on a rough field every component takes both signs.
    #[test]
    fn kept_point_normals_are_the_computed_ones() {
        let n = 9;
        let heights: Vec<f32> = (0..n * n)
            .map(|k| ((k * 7919 % 101) as f32 / 101.0).powi(2))
            .collect();
        let hf = HeightFieldData::new(n, n, Arc::new(heights), true, 0.0).unwrap();
        let fresh = |ix, iz| {
            let [x, y, z] = hf.quantised_normal(ix, iz).map(f64::from);
            DVec3::new(x, y * HEIGHT_UNITS, z).normalize_or(DVec3::Y)
        };
        let (mut negative_x, mut negative_z) = (0, 0);
        for pass in 0..2 {
            for k in 0..n * n {
                // The second pass visits the points in another order.
                let k = if pass == 0 { k } else { (k * 5) % (n * n) };
                let (ix, iz) = (k % n, k / n);
                let kept = hf.point_normal(ix, iz);
                assert_eq!(kept, fresh(ix, iz), "point ({ix}, {iz}), pass {pass}");
                assert_eq!(hf.clone().point_normal(ix, iz), kept);
                negative_x += usize::from(kept.x < 0.0);
                negative_z += usize::from(kept.z < 0.0);
            }
        }
        assert!(
            negative_x > 10 && negative_z > 10,
            "{negative_x} {negative_z}"
        );
    }

    #[test]
    fn inside_is_under_the_surface_above_zero() {
        let hf = field(5);
        assert!(hf.inside(DVec3::new(0.5, 0.2, 0.5)));
        assert!(!hf.inside(DVec3::new(0.5, 0.6, 0.5)));
        assert!(!hf.inside(DVec3::new(0.5, -0.1, 0.5)));
        assert!(!hf.inside(DVec3::new(1.5, 0.1, 0.5)));
    }

    #[test]
    fn smooth_normals_are_quantised_as_povray_stores_them() {
        // A ramp rising 0.19375 per cell (5 x 2 grid): POV-Ray's stored normal in height
        // units has y = 32767 / 12697 = 2.58, truncated to 2, so the slope it shows is
        // (1 / 32767) / (2 / 32767 / 65535) per cell: 1.0 in the unit square over 4 cells
        // (measured 0.992 to 0.998 at such points by scripts/hf_smooth_normals.py), where the
        // exact slope is 0.775.
        let heights: Vec<f32> = (0..10).map(|k| (k % 5) as f32 * 0.19375).collect();
        let hf = HeightFieldData::new(5, 2, Arc::new(heights), true, 0.0).unwrap();
        let n = hf.point_normal(2, 0);
        let slope_per_cell = -n.x / n.y;
        let slope = slope_per_cell * 4.0;
        let expected = 4.0 * NORMAL_UNITS / (2.0 * HEIGHT_UNITS);
        assert!((slope - expected).abs() < 1e-3, "{slope} vs {expected}");
        assert!(n.z.abs() < 1e-12);
    }
}
