//! The render-ready shapes: one enum, intersected in the shape's own space. Shapes whose
//! data would make every enum value large (quadrics, triangles, polygons) keep it in side
//! tables and hold an index, so the common spheres and boxes stay compact in the cache.

use std::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3};

use super::blob::BlobData;
use super::height_field::HeightFieldData;
use super::isosurface::IsoData;
use super::julia::JuliaData;
use super::mesh::MeshData;
use super::poly::PolyData;
use super::prism::PrismData;
use super::revolve::{LatheData, SorData};
use super::roots::{Roots, pair_from_q, quadratic, root_bound, roots_until};
use super::superellipsoid::Superellipsoid;
use super::{Aabb, Ray};

/// Data too large to sit inside [`ShapeKind`].
#[derive(Clone, Debug, Default)]
pub struct ShapeTables {
    /// POV-Ray's order: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J.
    pub quadrics: Vec<[f64; 10]>,
    /// POV-Ray's `quartic` order: descending powers of x, then y, then z (see QUARTIC_TERMS).
    pub quartics: Vec<[f64; 35]>,
    pub triangles: Vec<TriangleData>,
    pub polygons: Vec<PolygonData>,
    pub prisms: Vec<PrismData>,
    pub sors: Vec<SorData>,
    pub lathes: Vec<LatheData>,
    pub blobs: Vec<BlobData>,
    pub isosurfaces: Vec<IsoData>,
    pub meshes: Vec<MeshData>,
    pub height_fields: Vec<HeightFieldData>,
    pub polys: Vec<PolyData>,
    pub julias: Vec<JuliaData>,
}

impl ShapeTables {
    /// POV-Ray's warning for each isosurface whose function was steeper than its
    /// max_gradient, where roots may have been missed.
    pub fn gradient_notes(&self) -> Vec<String> {
        self.isosurfaces
            .iter()
            .filter_map(|iso| {
                let g = iso.gradient_exceeded()?;
                Some(format!(
                    "{}: the maximum gradient found was {g:.3}, but max_gradient of the isosurface was set to {:.3}; the surface may have holes",
                    iso.origin, iso.max_gradient
                ))
            })
            .collect()
    }

    /// Bytes held by the tables.
    pub fn memory_bytes(&self) -> usize {
        use std::mem::size_of;
        self.quadrics.capacity() * size_of::<[f64; 10]>()
            + self.triangles.capacity() * size_of::<TriangleData>()
            + self.polygons.capacity() * size_of::<PolygonData>()
            + self
                .polygons
                .iter()
                .map(|p| p.points.capacity() * 16 + p.loops.capacity() * 16)
                .sum::<usize>()
            + self
                .prisms
                .iter()
                .map(|p| size_of::<PrismData>() + p.profile.memory_bytes())
                .sum::<usize>()
            + self
                .sors
                .iter()
                .map(|s| size_of::<SorData>() + s.pieces.capacity() * 56)
                .sum::<usize>()
            + self
                .lathes
                .iter()
                .map(|l| size_of::<LatheData>() + l.profile.memory_bytes())
                .sum::<usize>()
            + self
                .blobs
                .iter()
                .map(|b| {
                    size_of::<BlobData>() + b.parts.capacity() * size_of::<super::blob::BlobPart>()
                })
                .sum::<usize>()
            + self.isosurfaces.capacity() * size_of::<IsoData>()
            + self
                .meshes
                .iter()
                .map(MeshData::memory_bytes)
                .sum::<usize>()
            + self
                .height_fields
                .iter()
                .map(HeightFieldData::memory_bytes)
                .sum::<usize>()
            + self.polys.iter().map(PolyData::memory_bytes).sum::<usize>()
            + self.julias.capacity() * size_of::<JuliaData>()
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleData {
    pub p0: DVec3,
    pub e1: DVec3,
    pub e2: DVec3,
    /// Vertex normals of a smooth triangle (interpolated for shading).
    pub normals: Option<[DVec3; 3]>,
}

/// A polygon in the plane z = 0 of its own frame (the primitive's transform places it),
/// filled by the even-odd rule so sub-polygons make holes, as in POV-Ray.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonData {
    pub points: Vec<DVec2>,
    /// Closed loops as ranges into `points` (each loop's last point joins its first).
    pub loops: Vec<(usize, usize)>,
    pub bounds: (DVec2, DVec2),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShapeKind {
    Sphere {
        center: DVec3,
        radius: f64,
    },
    /// Points with `normal . p = distance`.
    Plane {
        normal: DVec3,
        distance: f64,
    },
    Box {
        min: DVec3,
        max: DVec3,
    },
    /// Along z from 0 to 1 with radius `r0` at z = 0 and `r1` at z = 1 (a cylinder when
    /// equal); the transform places, turns and stretches it, without scaling x and y.
    Cone {
        r0: f64,
        r1: f64,
        open: bool,
    },
    /// In the plane z = 0, radius `radius` with a hole of `hole`.
    Disc {
        radius: f64,
        hole: f64,
    },
    /// Around the y axis: major radius in the xz plane, minor radius of the tube.
    Torus {
        major: f64,
        minor: f64,
    },
    Quadric(u32),
    Quartic(u32),
    Triangle(u32),
    Polygon(u32),
    /// A spline prism; it can cross a ray more often than [`Roots`] holds, so CSG reads its
    /// crossings through [`ShapeKind::each_hit`].
    Prism(u32),
    /// Surfaces of revolution, read the same way as prisms.
    Sor(u32),
    Lathe(u32),
    /// It can cross a ray more often than [`Roots`] holds (the pinched ones), so CSG reads
    /// its crossings through [`ShapeKind::each_hit`].
    Superellipsoid(Superellipsoid),
    /// Read the same way as superellipsoids.
    Blob(u32),
    /// Read the same way as superellipsoids.
    Isosurface(u32),
    /// Triangles with their own BVH; a hit names its face (`intersect_part`).
    Mesh(u32),
    /// A grid of heights; a hit names its cell and triangle.
    HeightField(u32),
    /// `poly`, `cubic`, `polynomial`: up to seven crossings, read as prisms are.
    Poly(u32),
    /// `julia_fractal`: read as prisms are.
    Julia(u32),
}

impl ShapeKind {
    /// Object-space bounds; `None` for unbounded shapes.
    pub fn bounds(&self, tables: &ShapeTables) -> Option<Aabb> {
        match *self {
            ShapeKind::Sphere { center, radius } => Some(Aabb::new(
                center - DVec3::splat(radius),
                center + DVec3::splat(radius),
            )),
            ShapeKind::Plane { .. }
            | ShapeKind::Quadric(_)
            | ShapeKind::Quartic(_)
            | ShapeKind::Poly(_) => None,
            ShapeKind::Box { min, max } => Some(Aabb::new(min, max)),
            ShapeKind::Cone { r0, r1, .. } => {
                let r = r0.abs().max(r1.abs());
                Some(Aabb::new(DVec3::new(-r, -r, 0.0), DVec3::new(r, r, 1.0)))
            }
            ShapeKind::Disc { radius, .. } => Some(Aabb::new(
                DVec3::new(-radius, -radius, 0.0),
                DVec3::new(radius, radius, 0.0),
            )),
            ShapeKind::Torus { major, minor } => {
                let r = major.abs() + minor.abs();
                Some(Aabb::new(
                    DVec3::new(-r, -minor.abs(), -r),
                    DVec3::new(r, minor.abs(), r),
                ))
            }
            ShapeKind::Triangle(i) => {
                let t = &tables.triangles[i as usize];
                Some(Aabb::new(t.p0, t.p0 + t.e1).grow(t.p0 + t.e2))
            }
            ShapeKind::Polygon(i) => {
                let (lo, hi) = tables.polygons[i as usize].bounds;
                Some(Aabb::new(lo.extend(0.0), hi.extend(0.0)))
            }
            ShapeKind::Prism(i) => Some(tables.prisms[i as usize].bounds()),
            ShapeKind::Sor(i) => Some(tables.sors[i as usize].bounds()),
            ShapeKind::Lathe(i) => Some(tables.lathes[i as usize].bounds()),
            ShapeKind::Superellipsoid(s) => Some(s.bounds()),
            ShapeKind::Blob(i) => Some(tables.blobs[i as usize].bounds),
            ShapeKind::Isosurface(i) => Some(tables.isosurfaces[i as usize].bounds()),
            ShapeKind::Mesh(i) => Some(tables.meshes[i as usize].bounds()),
            ShapeKind::HeightField(i) => Some(tables.height_fields[i as usize].bounds()),
            ShapeKind::Julia(i) => Some(tables.julias[i as usize].bounds()),
        }
    }

    /// Where the line lies inside the solid, for the convex solids whose span along a line
    /// is quick to find (an intersection or a clip keeps no crossing outside it).
    pub fn line_inside(&self, ray: &Ray, tables: &ShapeTables) -> LineInside {
        match *self {
            ShapeKind::Sphere { center, radius } => {
                LineInside::from_roots(&sphere_roots(ray, center, radius))
            }
            ShapeKind::Plane { normal, distance } => {
                // n.(o + t d) < distance
                let (at_origin, rate) =
                    (normal.dot(ray.origin) - distance, normal.dot(ray.direction));
                LineInside::below(at_origin, rate)
            }
            ShapeKind::Box { min, max } => box_crossings(ray, min, max)
                .map_or(LineInside::Never, |[(a, _), (b, _)]| {
                    LineInside::Between(a, b)
                }),
            ShapeKind::Quadric(i) => {
                let q = &tables.quadrics[i as usize];
                // Convex where its quadratic form is: no cross terms, no negative square.
                if q[3] != 0.0 || q[4] != 0.0 || q[5] != 0.0 || q[..3].iter().any(|&c| c < 0.0) {
                    return LineInside::Unknown;
                }
                let (qa, qb, qc) = quadric_along(ray, q);
                if qa == 0.0 {
                    LineInside::below(qc, qb)
                } else {
                    LineInside::from_roots(&quadratic(qa, qb, qc))
                }
            }
            _ => LineInside::Unknown,
        }
    }

    /// [`ShapeKind::each_hit_part`], but the shapes that search the whole line for their
    /// crossings (quartics, polys) search only `within` (the caller keeps only crossings
    /// there).
    pub fn each_hit_part_within(
        &self,
        ray: &Ray,
        tables: &ShapeTables,
        within: (f64, f64),
        mut f: impl FnMut(f64, u32),
    ) {
        match *self {
            ShapeKind::Quartic(i) => {
                quartic_crossings_within(ray, &tables.quartics[i as usize], within, |t| {
                    f(t, 0);
                    true
                });
            }
            ShapeKind::Poly(i) => {
                tables.polys[i as usize].each_hit_within(ray, within, |t| f(t, 0))
            }
            _ => self.each_hit_part(ray, tables, f),
        }
    }

    /// Object-space bounds of the solid with infinite sides where it is unbounded (a
    /// plane's half-space, a cylinder's axis), so that an intersection or a clip of
    /// unbounded shapes can have a box (shapesq.inc's quartics, clipped by a cylinder and
    /// two planes, were tested by every ray).
    pub fn extent(&self, tables: &ShapeTables) -> Aabb {
        if let Some(b) = self.bounds(tables) {
            return b;
        }
        match *self {
            ShapeKind::Plane { normal, distance } => half_space_extent(normal, distance),
            ShapeKind::Quadric(i) => quadric_extent(&tables.quadrics[i as usize]),
            _ => Aabb::INFINITE,
        }
    }

    /// Nearest hit distance in (0, t_max), in units of the ray's direction (which need not
    /// be normalised, so the same `t` holds in object and world space).
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f64, tables: &ShapeTables) -> Option<f64> {
        if let ShapeKind::Mesh(_) | ShapeKind::HeightField(_) = *self {
            return self.intersect_part(ray, t_max, tables).map(|h| h.0);
        }
        if let ShapeKind::Prism(_) | ShapeKind::Sor(_) | ShapeKind::Lathe(_) | ShapeKind::Poly(_) =
            *self
        {
            let mut best = t_max;
            self.each_hit(ray, tables, |t| {
                if t > 0.0 && t < best {
                    best = t;
                }
            });
            return (best < t_max).then_some(best);
        }
        if let ShapeKind::Isosurface(i) = *self {
            let mut found = None;
            tables.isosurfaces[i as usize].hits_from(ray, 0.0, |t| {
                if t > 0.0 {
                    found = (t < t_max).then_some(t);
                    return false;
                }
                true
            });
            return found;
        }
        if let ShapeKind::Torus { major, minor } = *self {
            return torus_first_hit(ray, major, minor, t_max);
        }
        if let ShapeKind::Quartic(i) = *self {
            return quartic_first_hit(ray, &tables.quartics[i as usize], t_max);
        }
        if let ShapeKind::Superellipsoid(_) | ShapeKind::Blob(_) | ShapeKind::Julia(_) = *self {
            // Crossings come in increasing order: stop at the first ahead of the origin.
            let mut found = None;
            self.crossings(ray, tables, |t| {
                if t > 0.0 {
                    found = (t < t_max).then_some(t);
                    return false;
                }
                true
            });
            return found;
        }
        let hits = self.all_hits(ray, tables);
        hits.as_slice()
            .iter()
            .copied()
            .find(|&t| t > 0.0 && t < t_max)
    }

    /// Like [`ShapeKind::intersect`], with the part of the shape hit (a mesh's face, a
    /// height field's triangle; 0 for shapes of one piece), which the normal, the uv and
    /// the material of meshes depend on.
    #[inline]
    pub fn intersect_part(
        &self,
        ray: &Ray,
        t_max: f64,
        tables: &ShapeTables,
    ) -> Option<(f64, u32)> {
        match *self {
            // The commonest shapes (every ray meets a scene's floor), tested here without
            // the general dispatch.
            ShapeKind::Sphere { center, radius } => {
                sphere_first_hit(ray, center, radius, t_max).map(|t| (t, 0))
            }
            ShapeKind::Plane { normal, distance } => {
                plane_hit(ray, normal, distance, t_max).map(|t| (t, 0))
            }
            ShapeKind::Mesh(i) => tables.meshes[i as usize].hit(ray, t_max),
            ShapeKind::HeightField(i) => tables.height_fields[i as usize].hit(ray, t_max),
            ShapeKind::Box { min, max } => box_crossings(ray, min, max)?
                .into_iter()
                .find(|&(t, _)| t > 0.0 && t < t_max),
            _ => self.intersect(ray, t_max, tables).map(|t| (t, 0)),
        }
    }

    /// Like [`ShapeKind::each_hit`], with the part of each crossing; meshes and height
    /// fields give only the crossings ahead of the ray's origin.
    #[inline]
    pub fn each_hit_part(&self, ray: &Ray, tables: &ShapeTables, mut f: impl FnMut(f64, u32)) {
        match *self {
            ShapeKind::Mesh(i) => tables.meshes[i as usize].each_hit(ray, f),
            ShapeKind::HeightField(i) => tables.height_fields[i as usize].each_hit(ray, f),
            ShapeKind::Box { min, max } => {
                for (t, face) in box_crossings(ray, min, max).into_iter().flatten() {
                    f(t, face);
                }
            }
            _ => self.each_hit(ray, tables, |t| f(t, 0)),
        }
    }

    /// The geometric and shading normals at a point on `part` (see `intersect_part`).
    pub fn normals(&self, p: DVec3, part: u32, tables: &ShapeTables) -> (DVec3, DVec3) {
        match *self {
            ShapeKind::Mesh(i) => {
                let m = &tables.meshes[i as usize];
                (m.normal(part), m.shading_normal(part, p))
            }
            ShapeKind::HeightField(i) => {
                let h = &tables.height_fields[i as usize];
                (h.normal(part), h.shading_normal(part, p))
            }
            ShapeKind::Box { .. } if part != 0 => {
                let n = box_face_normal(part);
                (n, n)
            }
            _ => {
                let n = self.normal(p, tables);
                (n, self.shading_normal_or(p, tables, n))
            }
        }
    }

    /// The surface's (u, v) at a point on `part` (see [`ShapeKind::uv`]).
    pub fn uv_on(&self, p: DVec3, part: u32, tables: &ShapeTables) -> Option<DVec2> {
        match *self {
            ShapeKind::Mesh(i) => tables.meshes[i as usize].uv(part, p),
            _ => self.uv(p),
        }
    }

    /// Calls `f` with every crossing of the surface along the whole line, in no particular
    /// order; CSG needs them all.
    #[inline]
    pub fn each_hit(&self, ray: &Ray, tables: &ShapeTables, mut f: impl FnMut(f64)) {
        match *self {
            ShapeKind::Prism(i) => tables.prisms[i as usize].each_hit(ray, f),
            ShapeKind::Sor(i) => tables.sors[i as usize].each_hit(ray, f),
            ShapeKind::Lathe(i) => tables.lathes[i as usize].each_hit(ray, f),
            ShapeKind::Poly(i) => tables.polys[i as usize].each_hit(ray, f),
            ShapeKind::Superellipsoid(_)
            | ShapeKind::Blob(_)
            | ShapeKind::Isosurface(_)
            | ShapeKind::Julia(_) => {
                self.crossings(ray, tables, |t| {
                    f(t);
                    true
                });
            }
            ShapeKind::Mesh(i) => tables.meshes[i as usize].each_hit(ray, |t, _| f(t)),
            ShapeKind::HeightField(i) => {
                tables.height_fields[i as usize].each_hit(ray, |t, _| f(t));
            }
            _ => {
                for &t in self.all_hits(ray, tables).as_slice() {
                    f(t);
                }
            }
        }
    }

    /// Whether [`ShapeKind::crossings_from`] finds the shape's crossings: in increasing
    /// order, each searched for only when the one before is taken.
    #[inline]
    pub fn finds_crossings_in_order(&self) -> bool {
        matches!(
            self,
            ShapeKind::Superellipsoid(_)
                | ShapeKind::Blob(_)
                | ShapeKind::Isosurface(_)
                | ShapeKind::Julia(_)
        )
    }

    /// The crossings of shapes that find them in increasing order, until `f` says stop.
    fn crossings(&self, ray: &Ray, tables: &ShapeTables, f: impl FnMut(f64) -> bool) {
        self.crossings_from(ray, tables, f64::NEG_INFINITY, f);
    }

    /// The crossings of shapes that find them in increasing order, from `t_min` on (some,
    /// isosurfaces, searching no further back), until `f` says stop.
    pub fn crossings_from(
        &self,
        ray: &Ray,
        tables: &ShapeTables,
        t_min: f64,
        f: impl FnMut(f64) -> bool,
    ) {
        match *self {
            ShapeKind::Isosurface(i) => tables.isosurfaces[i as usize].hits_from(ray, t_min, f),
            ShapeKind::Superellipsoid(s) => s.each_hit(ray, f),
            ShapeKind::Blob(i) => tables.blobs[i as usize].each_hit(ray, f),
            ShapeKind::Julia(i) => tables.julias[i as usize].each_hit(ray, f),
            _ => {}
        }
    }

    /// The crossings of the surface along the whole line, sorted, for shapes with at most
    /// four (prisms, surfaces of revolution, blobs and superellipsoids give their first four; use
    /// [`ShapeKind::each_hit`]).
    pub fn all_hits(&self, ray: &Ray, tables: &ShapeTables) -> Roots {
        match *self {
            ShapeKind::Sphere { center, radius } => sphere_roots(ray, center, radius),
            ShapeKind::Plane { normal, distance } => {
                let mut r = Roots::default();
                let denom = normal.dot(ray.direction);
                if denom != 0.0 {
                    r.push((distance - normal.dot(ray.origin)) / denom);
                }
                r
            }
            ShapeKind::Box { min, max } => {
                let mut r = Roots::default();
                for (t, _) in box_crossings(ray, min, max).into_iter().flatten() {
                    r.push(t);
                }
                r
            }
            ShapeKind::Cone { r0, r1, open } => cone_hits(ray, r0, r1, open),
            ShapeKind::Disc { radius, hole } => {
                let mut r = Roots::default();
                if ray.direction.z != 0.0 {
                    let t = -ray.origin.z / ray.direction.z;
                    let p = ray.at(t);
                    let d2 = p.x * p.x + p.y * p.y;
                    if d2 <= radius * radius && d2 >= hole * hole {
                        r.push(t);
                    }
                }
                r
            }
            ShapeKind::Torus { major, minor } => torus_hits(ray, major, minor),
            ShapeKind::Quadric(i) => quadric_hits(ray, &tables.quadrics[i as usize]),
            ShapeKind::Quartic(i) => quartic_hits(ray, &tables.quartics[i as usize]),
            ShapeKind::Triangle(i) => {
                let mut r = Roots::default();
                if let Some((t, _, _)) = triangle_hit(ray, &tables.triangles[i as usize]) {
                    r.push(t);
                }
                r
            }
            ShapeKind::Polygon(i) => {
                let mut r = Roots::default();
                if ray.direction.z != 0.0 {
                    let t = -ray.origin.z / ray.direction.z;
                    let p = ray.at(t);
                    if polygon_contains(&tables.polygons[i as usize], DVec2::new(p.x, p.y)) {
                        r.push(t);
                    }
                }
                r
            }
            ShapeKind::Prism(_) | ShapeKind::Sor(_) | ShapeKind::Lathe(_) | ShapeKind::Poly(_) => {
                let mut r = Roots::default();
                self.each_hit(ray, tables, |t| r.push(t));
                r.sort();
                r
            }
            ShapeKind::Superellipsoid(_)
            | ShapeKind::Blob(_)
            | ShapeKind::Isosurface(_)
            | ShapeKind::Julia(_) => {
                let mut r = Roots::default();
                self.each_hit(ray, tables, |t| r.push(t));
                r
            }
            ShapeKind::Mesh(_) | ShapeKind::HeightField(_) => {
                let mut r = Roots::default();
                self.each_hit(ray, tables, |t| r.push(t));
                r.sort();
                r
            }
        }
    }

    /// Outward geometric normal at a point on the surface, not normalised.
    pub fn normal(&self, p: DVec3, tables: &ShapeTables) -> DVec3 {
        match *self {
            ShapeKind::Sphere { center, .. } => p - center,
            ShapeKind::Plane { normal, .. } => normal,
            ShapeKind::Box { min, max } => {
                // The face whose plane the point is closest to, relative to the box size.
                let c = (min + max) * 0.5;
                let h = ((max - min) * 0.5).max(DVec3::splat(1e-300));
                let q = (p - c) / h;
                let a = q.abs();
                if a.x >= a.y && a.x >= a.z {
                    DVec3::new(q.x.signum(), 0.0, 0.0)
                } else if a.y >= a.z {
                    DVec3::new(0.0, q.y.signum(), 0.0)
                } else {
                    DVec3::new(0.0, 0.0, q.z.signum())
                }
            }
            ShapeKind::Cone { r0, r1, open } => {
                let radial = (p.x * p.x + p.y * p.y).sqrt();
                let r = r0 + (r1 - r0) * p.z;
                // Caps are flat: decide by which surface the point is nearer to.
                if !open {
                    let side = (radial - r.abs()).abs();
                    if p.z.abs() < side * 0.5 || (p.z <= 1e-9 && radial < r0.abs()) {
                        return -DVec3::Z;
                    }
                    if (p.z - 1.0).abs() < side * 0.5 || (p.z >= 1.0 - 1e-9 && radial < r1.abs()) {
                        return DVec3::Z;
                    }
                }
                DVec3::new(p.x, p.y, -r * (r1 - r0))
            }
            ShapeKind::Disc { .. } | ShapeKind::Polygon(_) => DVec3::Z,
            ShapeKind::Torus { major, .. } => {
                let radial = DVec3::new(p.x, 0.0, p.z);
                let len = radial.length();
                let ring = if len > 0.0 {
                    radial * (major / len)
                } else {
                    DVec3::ZERO
                };
                p - ring
            }
            ShapeKind::Quadric(i) => {
                let [a, b, c, d, e, f, g, h, ii, _] = tables.quadrics[i as usize];
                DVec3::new(
                    2.0 * a * p.x + d * p.y + e * p.z + g,
                    2.0 * b * p.y + d * p.x + f * p.z + h,
                    2.0 * c * p.z + e * p.x + f * p.y + ii,
                )
            }
            ShapeKind::Quartic(i) => quartic_gradient(&tables.quartics[i as usize], p),
            ShapeKind::Prism(i) => tables.prisms[i as usize].normal(p),
            ShapeKind::Sor(i) => tables.sors[i as usize].normal(p),
            ShapeKind::Lathe(i) => tables.lathes[i as usize].normal(p),
            ShapeKind::Superellipsoid(s) => s.gradient(p),
            ShapeKind::Blob(i) => tables.blobs[i as usize].normal(p),
            ShapeKind::Isosurface(i) => tables.isosurfaces[i as usize].normal(p),
            ShapeKind::Poly(i) => tables.polys[i as usize].gradient(p),
            ShapeKind::Julia(i) => tables.julias[i as usize].normal(p),
            ShapeKind::Triangle(i) => {
                let t = &tables.triangles[i as usize];
                t.e1.cross(t.e2)
            }
            // Without the part (see `normals`): the first face's.
            ShapeKind::Mesh(i) => tables.meshes[i as usize].normal(0),
            ShapeKind::HeightField(i) => tables.height_fields[i as usize].normal(0),
        }
    }

    /// The normal used for shading, given the geometric normal `normal` at `p`: the same
    /// for every shape but a smooth triangle, so not computed twice (an isosurface's takes
    /// six function evaluations).
    fn shading_normal_or(&self, p: DVec3, tables: &ShapeTables, normal: DVec3) -> DVec3 {
        if let ShapeKind::Triangle(i) = *self {
            let t = &tables.triangles[i as usize];
            if let Some(n) = t.normals {
                let (u, v) = barycentric(t, p);
                let s = n[0] * (1.0 - u - v) + n[1] * u + n[2] * v;
                if s.length_squared() > 0.0 {
                    return s;
                }
            }
        }
        normal
    }

    /// The surface's own (u, v) at an object-space point on it, for `uv_mapping`, as
    /// measured with povray (`uv_mapping gradient x` shows u, `gradient y` v):
    /// - sphere: u = atan2(z, x) / 2 pi (0 on +x, 1/4 on +z), v = 1/2 + asin(y) / pi;
    /// - box: the six faces unfolded into a cross, each face a quarter wide and a third high,
    ///   with s = (p - min) / (max - min): the middle row holds -x (u = s_z / 4), +z
    ///   (1/4 + s_x / 4), +x (3/4 - s_z / 4) and -z (1 - s_x / 4) at v = (1 + s_y) / 3;
    ///   +y sits above +z (v = 1 - s_z / 3) and -y below it (v = s_z / 3), so the cross
    ///   folds back into the box edge to edge;
    /// - torus: u = 1/2 - atan2(z, x) / 2 pi around y, v = 1/2 + theta / 2 pi with theta the
    ///   angle round the tube, 0 on the outer equator, pi/2 on top.
    ///
    /// Other shapes have none: povray then uses the world x and y of the point (`None`).
    pub fn uv(&self, p: DVec3) -> Option<DVec2> {
        match *self {
            ShapeKind::Sphere { center, .. } => {
                let d = (p - center).normalize_or(DVec3::Y);
                let u = (d.z.atan2(d.x) / TAU).rem_euclid(1.0);
                Some(DVec2::new(u, 0.5 + d.y.clamp(-1.0, 1.0).asin() / PI))
            }
            ShapeKind::Box { min, max } => {
                let size = (max - min).max(DVec3::splat(1e-300));
                let s = ((p - min) / size).clamp(DVec3::ZERO, DVec3::ONE);
                // The face: the coordinate nearest its bound, relative to the box size.
                let d = (s - DVec3::splat(0.5)).abs();
                let (u, v) = if d.x >= d.y && d.x >= d.z {
                    let v = (1.0 + s.y) / 3.0;
                    if s.x < 0.5 {
                        (s.z / 4.0, v)
                    } else {
                        (0.75 - s.z / 4.0, v)
                    }
                } else if d.z >= d.y {
                    let v = (1.0 + s.y) / 3.0;
                    if s.z < 0.5 {
                        (1.0 - s.x / 4.0, v)
                    } else {
                        (0.25 + s.x / 4.0, v)
                    }
                } else {
                    let u = 0.25 + s.x / 4.0;
                    if s.y < 0.5 {
                        (u, s.z / 3.0)
                    } else {
                        (u, 1.0 - s.z / 3.0)
                    }
                };
                Some(DVec2::new(u, v))
            }
            ShapeKind::Torus { major, .. } => {
                let u = (0.5 - p.z.atan2(p.x) / TAU).rem_euclid(1.0);
                let theta = p.y.atan2(p.x.hypot(p.z) - major);
                Some(DVec2::new(u, 0.5 + theta / TAU))
            }
            _ => None,
        }
    }

    /// Whether a point is inside the solid, POV-Ray's notion used by CSG. Points on the
    /// surface count as outside, the same way every time, so that coincident CSG faces
    /// resolve deterministically.
    pub fn inside(&self, p: DVec3, tables: &ShapeTables) -> bool {
        match *self {
            ShapeKind::Sphere { center, radius } => {
                (p - center).length_squared() < radius * radius * (1.0 - 1e-12)
            }
            ShapeKind::Plane { normal, distance } => {
                normal.dot(p) < distance - 1e-12 * (distance.abs() + p.abs().max_element())
            }
            ShapeKind::Box { min, max } => {
                let eps = 1e-12 * (min.abs().max(max.abs()).max_element() + 1.0);
                p.cmpgt(min + eps).all() && p.cmplt(max - eps).all()
            }
            ShapeKind::Cone { r0, r1, .. } => {
                let r = r0 + (r1 - r0) * p.z;
                p.z > 0.0 && p.z < 1.0 && p.x * p.x + p.y * p.y < r * r * (1.0 - 1e-12)
            }
            ShapeKind::Torus { major, minor } => {
                let q = DVec2::new(DVec2::new(p.x, p.z).length() - major, p.y);
                q.length_squared() < minor * minor * (1.0 - 1e-12)
            }
            ShapeKind::Quadric(i) => quadric_value(&tables.quadrics[i as usize], p) < 0.0,
            ShapeKind::Quartic(i) => quartic_value(&tables.quartics[i as usize], p) < 0.0,
            ShapeKind::Prism(i) => tables.prisms[i as usize].inside(p),
            ShapeKind::Sor(i) => tables.sors[i as usize].inside(p),
            ShapeKind::Lathe(i) => tables.lathes[i as usize].inside(p),
            ShapeKind::Superellipsoid(s) => s.inside(p),
            ShapeKind::Blob(i) => tables.blobs[i as usize].inside(p),
            ShapeKind::Isosurface(i) => tables.isosurfaces[i as usize].inside(p),
            ShapeKind::Mesh(i) => tables.meshes[i as usize].inside(p),
            ShapeKind::HeightField(i) => tables.height_fields[i as usize].inside(p),
            ShapeKind::Poly(i) => tables.polys[i as usize].inside(p),
            ShapeKind::Julia(i) => tables.julias[i as usize].inside(p),
            ShapeKind::Disc { .. } | ShapeKind::Triangle(_) | ShapeKind::Polygon(_) => false,
        }
    }
}

/// Where a ray meets the plane n . p = distance within (0, t_max).
#[inline(always)]
pub fn plane_hit(ray: &Ray, normal: DVec3, distance: f64, t_max: f64) -> Option<f64> {
    let denom = normal.dot(ray.direction);
    let t = (distance - normal.dot(ray.origin)) / denom;
    (denom != 0.0 && t > 0.0 && t < t_max).then_some(t)
}

/// A sphere's first crossing in (0, t_max), for callers that test spheres before any
/// general dispatch (most items in a scene of many objects are spheres). The roots are
/// those of `sphere_roots`, read in place rather than through a root list.
#[inline(always)]
pub fn sphere_first_hit(ray: &Ray, center: DVec3, radius: f64, t_max: f64) -> Option<f64> {
    let (q, a, c) = sphere_q(ray, center, radius, true)?;
    let [near, far, ..] = pair_from_q(q, a, c).values;
    let ahead = |t: f64| t > 0.0 && t < t_max;
    if ahead(near) {
        Some(near)
    } else {
        ahead(far).then_some(far)
    }
}

/// Both roots of the ray-sphere quadratic, ordered, computed without catastrophic
/// cancellation: the discriminant from the perpendicular distance to the centre, and the
/// second root from the product of roots (q = -(b + sign(b) sqrt(disc)), t0 = q/a, t1 = c/q).
#[inline(always)]
fn sphere_roots(ray: &Ray, center: DVec3, radius: f64) -> Roots {
    sphere_q(ray, center, radius, false).map_or(Roots::default(), |(q, a, c)| pair_from_q(q, a, c))
}

/// The quadratic's q, a and c (roots q/a and c/q), or none where the ray misses the sphere;
/// with `ahead_only`, none too where both roots are <= 0 and found cheaply so.
#[inline(always)]
fn sphere_q(ray: &Ray, center: DVec3, radius: f64, ahead_only: bool) -> Option<(f64, f64, f64)> {
    let d = ray.direction;
    let oc = ray.origin - center;
    let a = d.dot(d);
    if a == 0.0 {
        return None;
    }
    let b = oc.dot(d); // half of the usual b
    let c = oc.dot(oc) - radius * radius;
    // A clear miss, found without the division below: b^2 - a c is the discriminant too,
    // and where it is below zero by far more than its rounding error (a few ulps of
    // a (|oc|^2 + r^2)), the careful form below is negative as well.
    if b * b - a * c < -1e-9 * a * (oc.dot(oc) + radius * radius) {
        return None;
    }
    // A ray that starts on or outside the sphere (c >= 0) and heads away from its centre
    // (b >= 0) meets it at no t > 0: the roots' product c/a is not negative and their sum
    // -2b/a not positive. The careful form below finds the same in floating point (its
    // roots are q/a and c/q with q <= 0), only later: a shadow ray leaving the sphere it
    // starts on took its division and square root every time.
    if ahead_only && b.is_sign_positive() && c >= 0.0 {
        return None;
    }
    let perp = oc - d * (b / a);
    let disc = a * (radius * radius - perp.dot(perp));
    if disc < 0.0 {
        return None;
    }
    // b here is half the usual coefficient, so q carries no factor 1/2.
    Some((-(b + b.signum() * disc.sqrt()), a, c))
}

fn cone_hits(ray: &Ray, r0: f64, r1: f64, open: bool) -> Roots {
    let (o, d) = (ray.origin, ray.direction);
    let k = r1 - r0;
    // x^2 + y^2 - (r0 + k z)^2 = 0
    let rz_o = r0 + k * o.z;
    let a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
    let b = 2.0 * (o.x * d.x + o.y * d.y - rz_o * k * d.z);
    let c = o.x * o.x + o.y * o.y - rz_o * rz_o;
    let mut out = Roots::default();
    for &t in quadratic(a, b, c).as_slice() {
        let z = o.z + t * d.z;
        if (0.0..=1.0).contains(&z) {
            out.push(t);
        }
    }
    if !open && d.z != 0.0 {
        for (z, r) in [(0.0, r0), (1.0, r1)] {
            let t = (z - o.z) / d.z;
            let p = ray.at(t);
            if p.x * p.x + p.y * p.y <= r * r {
                out.push(t);
            }
        }
    }
    out.sort();
    out
}

fn torus_hits(ray: &Ray, major: f64, minor: f64) -> Roots {
    let mut out = Roots::default();
    torus_crossings(ray, major, minor, |t| {
        out.push(t);
        true
    });
    out
}

/// The first crossing of a torus in (0, t_max): [`torus_hits`]' first there, found without
/// the roots after it (a quarter of scenes/shape_quadrics.pov's instructions went to the
/// torus's roots, most of them to crossings no ray used).
fn torus_first_hit(ray: &Ray, major: f64, minor: f64, t_max: f64) -> Option<f64> {
    let mut found = None;
    torus_crossings(ray, major, minor, |t| {
        if t > 0.0 && t < t_max {
            found = Some(t);
        }
        found.is_none() && t < t_max
    });
    found
}

/// The crossings of a torus along a ray, in increasing order, given to `take` until it
/// returns false.
fn torus_crossings(ray: &Ray, major: f64, minor: f64, mut take: impl FnMut(f64) -> bool) {
    let d_len = ray.direction.length();
    let dir = ray.direction / d_len;
    // Most rays that reach a torus's box miss it: its bounds reject them before the
    // quartic, and the roots of the rest are looked for only within the bounds.
    let Some((enter, leave)) = torus_span(ray.origin, dir, major, minor) else {
        return;
    };
    // Start the polynomial where the ray enters the bounds, so its coefficients do not
    // cancel for far rays.
    let o = ray.origin + dir * enter;
    let (r2, s2) = (major * major, minor * minor);
    // (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2) with p = o + t dir, |dir| = 1.
    let od = o.dot(dir);
    let oo = o.dot(o);
    let k = oo + r2 - s2;
    let c4 = 1.0;
    let c3 = 4.0 * od;
    let c2 = 2.0 * k + 4.0 * od * od - 4.0 * r2 * (dir.x * dir.x + dir.z * dir.z);
    let c1 = 4.0 * k * od - 8.0 * r2 * (o.x * dir.x + o.z * dir.z);
    let c0 = k * k - 4.0 * r2 * (o.x * o.x + o.z * o.z);
    // The bounds touch the torus (its outer equator, its top and bottom circles): a
    // margin keeps a root there from falling outside by a rounding.
    let margin = 1e-7 * (major.abs() + minor.abs());
    let coef = [c4, c3, c2, c1, c0];
    roots_until(&coef, -margin, leave - enter + margin, |t| {
        take((t + enter) / d_len)
    });
}

/// Where a ray (unit direction) is within a torus's bounds: the sphere of radius R + r and
/// the slab |y| <= r. `None` where it never is.
fn torus_span(o: DVec3, dir: DVec3, major: f64, minor: f64) -> Option<(f64, f64)> {
    let bound = major.abs() + minor.abs();
    let b = o.dot(dir);
    // The distance from the centre to the line, without the cancellation of b^2 - c.
    let perp = o - dir * b;
    let disc = bound * bound - perp.dot(perp);
    if disc < 0.0 {
        return None;
    }
    let half = disc.sqrt();
    let (mut enter, mut leave) = (-b - half, -b + half);
    let r = minor.abs();
    if dir.y != 0.0 {
        let (a, e) = ((-r - o.y) / dir.y, (r - o.y) / dir.y);
        enter = enter.max(a.min(e));
        leave = leave.min(a.max(e));
    } else if o.y.abs() > r {
        return None;
    }
    (enter <= leave).then_some((enter, leave))
}

/// Where a line lies inside a solid ([`ShapeKind::line_inside`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LineInside {
    /// Not found for this shape.
    Unknown,
    /// Nowhere.
    Never,
    /// Between these distances (either may be infinite).
    Between(f64, f64),
}

impl LineInside {
    /// Inside between two roots (a convex solid's crossings), nowhere with fewer.
    fn from_roots(roots: &Roots) -> LineInside {
        match *roots.as_slice() {
            [a, b] => LineInside::Between(a, b),
            _ => LineInside::Never,
        }
    }

    /// Where `at_origin + rate t` is below zero.
    fn below(at_origin: f64, rate: f64) -> LineInside {
        let t = -at_origin / rate;
        if rate > 0.0 {
            LineInside::Between(f64::NEG_INFINITY, t)
        } else if rate < 0.0 {
            LineInside::Between(t, f64::INFINITY)
        } else if at_origin < 0.0 {
            LineInside::Between(f64::NEG_INFINITY, f64::INFINITY)
        } else {
            LineInside::Never
        }
    }
}

/// The half-space n.p <= d where n lies along an axis; otherwise everywhere.
fn half_space_extent(normal: DVec3, distance: f64) -> Aabb {
    let axes: Vec<usize> = (0..3).filter(|&k| normal[k] != 0.0).collect();
    let [k] = axes[..] else {
        return Aabb::INFINITE;
    };
    let mut out = Aabb::INFINITE;
    let bound = distance / normal[k];
    let bound = bound + pad(bound) * normal[k].signum();
    if normal[k] > 0.0 {
        out.max[k] = bound;
    } else {
        out.min[k] = bound;
    }
    out
}

/// A little more than the rounding of a bound computed at `v`.
fn pad(v: f64) -> f64 {
    1e-9 * (v.abs() + 1.0)
}

/// The box around a quadric's solid (value < 0) without cross terms: along each axis with
/// a positive square term the solid is an ellipse's or ellipsoid's extent, along an axis
/// without any term it is unbounded (a cylinder), and with a negative square term or a
/// linear term alone (cones, hyperboloids, paraboloids) everywhere.
fn quadric_extent(q: &[f64; 10]) -> Aabb {
    let [a, b, c, d, e, f, g, h, i, j] = *q;
    if d != 0.0 || e != 0.0 || f != 0.0 {
        return Aabb::INFINITE;
    }
    let terms = [(a, g), (b, h), (c, i)];
    if terms
        .iter()
        .any(|&(sq, lin)| sq < 0.0 || (sq == 0.0 && lin != 0.0))
    {
        return Aabb::INFINITE;
    }
    // sum sq (x + lin / 2 sq)^2 < r: the completed squares.
    let r = terms
        .iter()
        .filter(|t| t.0 > 0.0)
        .map(|&(sq, lin)| lin * lin / (4.0 * sq))
        .sum::<f64>()
        - j;
    if r <= 0.0 {
        return Aabb::EMPTY;
    }
    let mut out = Aabb::INFINITE;
    for (k, &(sq, lin)) in terms.iter().enumerate() {
        if sq > 0.0 {
            let (centre, half) = (-lin / (2.0 * sq), (r / sq).sqrt());
            let slack = pad(centre.abs() + half);
            out.min[k] = centre - half - slack;
            out.max[k] = centre + half + slack;
        }
    }
    out
}

fn quadric_value(q: &[f64; 10], p: DVec3) -> f64 {
    let [a, b, c, d, e, f, g, h, i, j] = *q;
    a * p.x * p.x
        + b * p.y * p.y
        + c * p.z * p.z
        + d * p.x * p.y
        + e * p.x * p.z
        + f * p.y * p.z
        + g * p.x
        + h * p.y
        + i * p.z
        + j
}

fn quadric_hits(ray: &Ray, q: &[f64; 10]) -> Roots {
    let (qa, qb, qc) = quadric_along(ray, q);
    quadratic(qa, qb, qc)
}

/// The quadric along the ray: qa t^2 + qb t + qc.
fn quadric_along(ray: &Ray, q: &[f64; 10]) -> (f64, f64, f64) {
    let [a, b, c, d, e, f, g, h, i, _] = *q;
    let (o, v) = (ray.origin, ray.direction);
    let qa = a * v.x * v.x
        + b * v.y * v.y
        + c * v.z * v.z
        + d * v.x * v.y
        + e * v.x * v.z
        + f * v.y * v.z;
    let qb = 2.0 * (a * o.x * v.x + b * o.y * v.y + c * o.z * v.z)
        + d * (o.x * v.y + o.y * v.x)
        + e * (o.x * v.z + o.z * v.x)
        + f * (o.y * v.z + o.z * v.y)
        + g * v.x
        + h * v.y
        + i * v.z;
    (qa, qb, quadric_value(q, o))
}

/// The exponents (x, y, z) of the 35 terms of a quartic, in POV-Ray's order.
const QUARTIC_TERMS: [(u8, u8, u8); 35] = {
    let mut out = [(0u8, 0u8, 0u8); 35];
    let mut n = 0;
    let mut i = 4i32;
    while i >= 0 {
        let mut j = 4 - i;
        while j >= 0 {
            let mut k = 4 - i - j;
            while k >= 0 {
                out[n] = (i as u8, j as u8, k as u8);
                n += 1;
                k -= 1;
            }
            j -= 1;
        }
        i -= 1;
    }
    out
};

/// v^0 .. v^4 as `powi` forms them (by squaring: v^3 = v v^2, v^4 = v^2 v^2), bit for bit,
/// without its call and loop for each power of each term (a tenth of incdemo/logo.pov).
fn powers4(v: f64) -> [f64; 5] {
    let v2 = v * v;
    [1.0, v, v2, v * v2, v2 * v2]
}

fn quartic_value(q: &[f64; 35], p: DVec3) -> f64 {
    let (px, py, pz) = (powers4(p.x), powers4(p.y), powers4(p.z));
    QUARTIC_TERMS
        .iter()
        .zip(q)
        .map(|(&(i, j, k), c)| c * px[i as usize] * py[j as usize] * pz[k as usize])
        .sum()
}

fn quartic_gradient(q: &[f64; 35], p: DVec3) -> DVec3 {
    let (px, py, pz) = (powers4(p.x), powers4(p.y), powers4(p.z));
    let pw = |v: usize, e: u8| [px, py, pz][v][e as usize];
    let mut g = DVec3::ZERO;
    for (&(i, j, k), &c) in QUARTIC_TERMS.iter().zip(q) {
        if c == 0.0 {
            continue;
        }
        if i > 0 {
            g.x += c * i as f64 * pw(0, i - 1) * pw(1, j) * pw(2, k);
        }
        if j > 0 {
            g.y += c * j as f64 * pw(0, i) * pw(1, j - 1) * pw(2, k);
        }
        if k > 0 {
            g.z += c * k as f64 * pw(0, i) * pw(1, j) * pw(2, k - 1);
        }
    }
    g
}

/// The quartic's crossings ahead of the ray's origin, but those at it ([`quartic_crossings`]).
fn quartic_hits(ray: &Ray, q: &[f64; 35]) -> Roots {
    let mut out = Roots::default();
    quartic_crossings(ray, q, |t| {
        out.push(t);
        true
    });
    out
}

/// The first crossing of a quartic in (0, t_max): [`quartic_hits`]' first there, found
/// without the roots after it.
fn quartic_first_hit(ray: &Ray, q: &[f64; 35], t_max: f64) -> Option<f64> {
    let mut found = None;
    quartic_crossings(ray, q, |t| {
        if t > 0.0 && t < t_max {
            found = Some(t);
        }
        t <= 0.0
    });
    found
}

/// The quartic along the ray as a polynomial in t (each coordinate is linear in t, so each
/// term is a product of small powers), then its real roots ahead of the origin, in
/// increasing order, given to `take` until it returns false; those within
/// [`QUARTIC_DEPTH_TOLERANCE`] of the origin are passed over.
fn quartic_crossings(ray: &Ray, q: &[f64; 35], take: impl FnMut(f64) -> bool) {
    quartic_crossings_within(ray, q, (0.0, f64::INFINITY), take);
}

/// [`quartic_crossings`] searched only within (lo, hi) (lo at least 0).
fn quartic_crossings_within(
    ray: &Ray,
    q: &[f64; 35],
    (lo, hi): (f64, f64),
    mut take: impl FnMut(f64) -> bool,
) {
    let coef = quartic_along(ray, q);
    let d_len = ray.direction.length().max(1e-300);
    // Every root lies within Fujiwara's bound: the last monotone piece ends there, not a
    // million units out (helix.pov: Newton's steps from out there took most of its render).
    let reach = (1e6 * (ray.origin.length() + 1.0) / d_len).min(root_bound(&coef));
    let tolerance = QUARTIC_DEPTH_TOLERANCE / d_len;
    // Only crossings ahead of the origin are ever used (as every shape's): the search
    // starts at it rather than a bound behind it, whose pieces would be solved only to be
    // dropped.
    let (lo, hi) = (lo.max(0.0), hi.min(reach));
    if lo < hi {
        roots_until(&coef, lo, hi, |t| t <= tolerance || take(t));
    }
}

/// The quartic along the ray, q(o + t d), as coefficients of t^4 down to t^0: each
/// coordinate is linear in t, so each term is a product of the coordinates' powers.
fn quartic_along(ray: &Ray, q: &[f64; 35]) -> [f64; 5] {
    // powers[axis][n]: (o + t d)^n as coefficients of t^0..t^4.
    let mut powers = [[[0.0f64; 5]; 5]; 3];
    for (axis, p) in powers.iter_mut().enumerate() {
        let (o, d) = (ray.origin[axis], ray.direction[axis]);
        p[0][0] = 1.0;
        for n in 1..5 {
            let prev = p[n - 1];
            let mut next = [0.0; 5];
            for m in 0..5 {
                next[m] += prev[m] * o;
                if m + 1 < 5 {
                    next[m + 1] += prev[m] * d;
                }
            }
            p[n] = next;
        }
    }
    let mul = |a: &[f64; 5], b: &[f64; 5]| {
        let mut out = [0.0; 5];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate().take(5 - i) {
                out[i + j] += x * y;
            }
        }
        out
    };
    let mut poly = [0.0f64; 5];
    for (&(i, j, k), &c) in QUARTIC_TERMS.iter().zip(q) {
        if c == 0.0 {
            continue;
        }
        // A power 0 is the polynomial 1, whose product gives the other factor back.
        let (px, py, pz) = (
            &powers[0][i as usize],
            &powers[1][j as usize],
            &powers[2][k as usize],
        );
        let xy = match (i, j) {
            (_, 0) => *px,
            (0, _) => *py,
            _ => mul(px, py),
        };
        let term = if k == 0 { xy } else { mul(&xy, pz) };
        for m in 0..5 {
            poly[m] += c * term[m];
        }
    }
    [poly[4], poly[3], poly[2], poly[1], poly[0]]
}

/// How close to its origin (in the quartic's own units) a ray ignores the surface. A ray
/// leaving a quartic starts on it only up to the root's error, which near a tangency is the
/// square root of the rounding error, far above the generic offset: shadow rays then found
/// the surface they left (dark rims on grafbic's Bicorn). POV-Ray skips such roots too:
/// through a transparent slab `x^2 - h^2` it sees the second face when 2h = 1.02e-4, not
/// when 2h = 0.98e-4.
const QUARTIC_DEPTH_TOLERANCE: f64 = 1e-4;

/// Möller-Trumbore: distance and barycentric (u, v) of the hit.
fn triangle_hit(ray: &Ray, t: &TriangleData) -> Option<(f64, f64, f64)> {
    let p = ray.direction.cross(t.e2);
    let det = t.e1.dot(p);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let s = ray.origin - t.p0;
    let u = s.dot(p) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(t.e1);
    let v = ray.direction.dot(q) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    Some((t.e2.dot(q) * inv, u, v))
}

fn barycentric(t: &TriangleData, p: DVec3) -> (f64, f64) {
    let n = t.e1.cross(t.e2);
    let nn = n.length_squared();
    if nn == 0.0 {
        return (0.0, 0.0);
    }
    let w = p - t.p0;
    let u = w.cross(t.e2).dot(n) / nn;
    let v = t.e1.cross(w).dot(n) / nn;
    (u, v)
}

fn polygon_contains(poly: &PolygonData, p: DVec2) -> bool {
    let (lo, hi) = poly.bounds;
    if p.x < lo.x || p.y < lo.y || p.x > hi.x || p.y > hi.y {
        return false;
    }
    let mut inside = false;
    for &(start, end) in &poly.loops {
        let pts = &poly.points[start..end];
        let n = pts.len();
        for k in 0..n {
            let (a, b) = (pts[k], pts[(k + 1) % n]);
            if (a.y > p.y) != (b.y > p.y) {
                let x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                if p.x < x {
                    inside = !inside;
                }
            }
        }
    }
    inside
}

/// Where a ray enters and leaves a box, each with the face it crosses (`box_face_normal`).
/// The faces come from the slabs, not from the point, so a box flat in one axis (POV-Ray
/// scenes use them as double-sided rectangles) is entered through the face the ray meets
/// and left through the other, as POV-Ray does.
fn box_crossings(ray: &Ray, min: DVec3, max: DVec3) -> Option<[(f64, u32); 2]> {
    let inv = ray.direction.recip();
    let t1 = (min - ray.origin) * inv;
    let t2 = (max - ray.origin) * inv;
    let near = t1.min(t2);
    let far = t1.max(t2);
    let (t_near, t_far) = (near.max_element(), far.min_element());
    if t_near > t_far || t_near.is_nan() || t_far.is_nan() {
        return None;
    }
    let axis_of = |v: DVec3, t: f64| (0..3).find(|&a| v[a] == t).unwrap_or(0);
    let (a_in, a_out) = (axis_of(near, t_near), axis_of(far, t_far));
    // Entering faces the ray; leaving, away from it.
    let face =
        |axis: usize, outward_positive: bool| (axis as u32) * 2 + 1 + u32::from(outward_positive);
    Some([
        (t_near, face(a_in, ray.direction[a_in] < 0.0)),
        (t_far, face(a_out, ray.direction[a_out] > 0.0)),
    ])
}

/// The outward normal of a box face numbered by `box_crossings` (1 + 2 axis, + 1 for the
/// face on the positive side).
fn box_face_normal(face: u32) -> DVec3 {
    let axis = ((face - 1) / 2) as usize;
    let mut n = DVec3::ZERO;
    n[axis] = if (face - 1) % 2 == 1 { 1.0 } else { -1.0 };
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quartic's powers are `powi`'s, to the last bit, over magnitudes from 1e-3 to 1e3.
    #[test]
    fn quartic_powers_are_powi() {
        let mut v = 1e-3f64;
        while v < 1e3 {
            for x in [v, -v, v * 1.000_000_1] {
                for (e, &p) in powers4(x).iter().enumerate() {
                    // The exponent hidden from the optimiser, as the terms' were (a constant
                    // one may be expanded otherwise).
                    let powi = x.powi(std::hint::black_box(e as i32));
                    assert_eq!(p.to_bits(), powi.to_bits(), "{x}^{e}");
                }
            }
            v *= 1.37;
        }
    }

    fn no_tables() -> ShapeTables {
        ShapeTables::default()
    }

    fn sphere(c: DVec3, r: f64) -> ShapeKind {
        ShapeKind::Sphere {
            center: c,
            radius: r,
        }
    }

    fn hit(s: &ShapeKind, ray: &Ray) -> Option<f64> {
        s.intersect(ray, f64::INFINITY, &no_tables())
    }

    #[test]
    fn sphere_hit_from_outside_and_inside() {
        let s = sphere(DVec3::new(0.0, 0.0, 5.0), 1.0);
        assert_eq!(hit(&s, &Ray::new(DVec3::ZERO, DVec3::Z)), Some(4.0));
        assert_eq!(
            hit(&s, &Ray::new(DVec3::new(0.0, 0.0, 5.0), DVec3::Z)),
            Some(1.0)
        );
        assert_eq!(hit(&s, &Ray::new(DVec3::ZERO, -DVec3::Z)), None);
        assert_eq!(
            s.intersect(&Ray::new(DVec3::ZERO, DVec3::Z), 3.9, &no_tables()),
            None
        );
    }

    #[test]
    fn tangent_rays_hit_or_miss_correctly() {
        let s = sphere(DVec3::new(0.0, 0.0, 10.0), 1.0);
        for k in 1..=7 {
            let e = 10f64.powi(-k);
            let inside = Ray::new(DVec3::new(1.0 - e, 0.0, 0.0), DVec3::Z);
            let outside = Ray::new(DVec3::new(1.0 + e, 0.0, 0.0), DVec3::Z);
            assert!(hit(&s, &inside).is_some(), "k={k}");
            assert!(hit(&s, &outside).is_none(), "k={k}");
        }
    }

    #[test]
    fn far_and_huge_spheres_hit_on_the_surface() {
        for (dist, r) in [(1e4, 1.0), (1e7, 1.0), (1e6, 1e4), (10.0, 1e-3)] {
            let c = DVec3::new(0.3 * r, 0.2 * r, dist);
            let s = sphere(c, r);
            let ray = Ray::new(DVec3::ZERO, DVec3::Z);
            let t = hit(&s, &ray).expect("hit");
            let err = ((ray.at(t) - c).length() - r).abs();
            assert!(err <= 8.0 * f64::EPSILON * dist.max(r), "{dist} {r}: {err}");
        }
    }

    #[test]
    fn uv_coordinates_match_povray() {
        let close = |a: Option<DVec2>, u: f64, v: f64| {
            let a = a.expect("uv");
            (a.x - u).abs() < 1e-9 && (a.y - v).abs() < 1e-9
        };
        // Sphere (measured from -z and +z): u = 3/4 facing -z, 1/4 facing +z, 1/2 on -x.
        let s = sphere(DVec3::new(1.0, 2.0, 3.0), 2.0);
        let c = DVec3::new(1.0, 2.0, 3.0);
        assert!(close(s.uv(c - 2.0 * DVec3::Z), 0.75, 0.5));
        assert!(close(s.uv(c + 2.0 * DVec3::Z), 0.25, 0.5));
        assert!(close(s.uv(c - 2.0 * DVec3::X), 0.5, 0.5));
        assert!(close(s.uv(c + 2.0 * DVec3::Y), 0.0, 1.0));
        // Box <0.1,0.2,0.05> - <0.9,0.6,0.95> (measured faces, s = (p - min) / size).
        let b = ShapeKind::Box {
            min: DVec3::new(0.1, 0.2, 0.05),
            max: DVec3::new(0.9, 0.6, 0.95),
        };
        let at = |s: DVec3| DVec3::new(0.1, 0.2, 0.05) + s * DVec3::new(0.8, 0.4, 0.9);
        assert!(close(b.uv(at(DVec3::new(0.0, 0.5, 0.2))), 0.05, 0.5)); // -x
        assert!(close(b.uv(at(DVec3::new(0.4, 0.5, 1.0))), 0.35, 0.5)); // +z
        assert!(close(b.uv(at(DVec3::new(1.0, 0.5, 0.2))), 0.7, 0.5)); // +x
        assert!(close(b.uv(at(DVec3::new(0.4, 0.5, 0.0))), 0.9, 0.5)); // -z
        assert!(close(b.uv(at(DVec3::new(0.4, 1.0, 0.3))), 0.35, 0.9)); // +y
        assert!(close(b.uv(at(DVec3::new(0.4, 0.0, 0.3))), 0.35, 0.1)); // -y
        // Torus (measured): u = 1/2 - atan2(z, x) / 2 pi, so 3/4 facing -z; v = 1/2 on the
        // outer equator, 3/4 on top of the tube, 1/4 below it.
        let t = ShapeKind::Torus {
            major: 0.3,
            minor: 0.1,
        };
        assert!(close(t.uv(DVec3::new(0.0, 0.0, -0.4)), 0.75, 0.5));
        assert!(close(t.uv(DVec3::new(0.3, 0.1, 0.0)), 0.5, 0.75));
        assert!(close(t.uv(DVec3::new(0.3, -0.1, 0.0)), 0.5, 0.25));
        assert!(
            ShapeKind::Disc {
                radius: 1.0,
                hole: 0.0
            }
            .uv(DVec3::ZERO)
            .is_none()
        );
    }

    #[test]
    fn box_and_plane() {
        let b = ShapeKind::Box {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        };
        let ray = Ray::new(DVec3::new(0.5, 0.0, -5.0), DVec3::Z);
        let t = hit(&b, &ray).unwrap();
        assert_eq!(t, 4.0);
        assert_eq!(
            b.normal(ray.at(t), &no_tables()),
            DVec3::new(0.0, 0.0, -1.0)
        );
        assert!(b.inside(DVec3::ZERO, &no_tables()) && !b.inside(DVec3::splat(2.0), &no_tables()));
        let p = ShapeKind::Plane {
            normal: DVec3::Y,
            distance: -1.0,
        };
        let t = hit(&p, &Ray::new(DVec3::ZERO, DVec3::new(0.0, -1.0, 1.0)));
        assert_eq!(t, Some(1.0));
        assert!(p.inside(DVec3::new(0.0, -2.0, 0.0), &no_tables()));
    }

    #[test]
    fn a_flat_box_is_entered_through_the_face_the_ray_meets() {
        // Flat in z, as POV-Ray scenes write double-sided rectangles
        // (textures/finishes/var_reflection.pov).
        let b = ShapeKind::Box {
            min: DVec3::new(-1.0, -1.0, 0.25),
            max: DVec3::new(1.0, 1.0, 0.25),
        };
        let t = no_tables();
        for (from, outward) in [(1.0, DVec3::Z), (-1.0, -DVec3::Z)] {
            let ray = Ray::new(
                DVec3::new(0.3, 0.2, 0.25 + from),
                DVec3::new(0.1, 0.0, -from),
            );
            let (hit, part) = b.intersect_part(&ray, f64::INFINITY, &t).unwrap();
            assert_eq!(hit, 1.0);
            assert_eq!(b.normals(ray.at(hit), part, &t).0, outward);
            let mut crossings = Vec::new();
            b.each_hit_part(&ray, &t, |t, part| crossings.push((t, part)));
            assert_eq!(crossings.len(), 2);
            assert_eq!(b.normals(ray.at(1.0), crossings[1].1, &t).0, -outward);
        }
        // A ray in the box's plane misses it.
        let along = Ray::new(DVec3::new(-5.0, 0.0, 0.25), DVec3::X);
        assert_eq!(b.intersect_part(&along, f64::INFINITY, &t), None);
    }

    #[test]
    fn cylinder_cone_disc() {
        let cyl = ShapeKind::Cone {
            r0: 1.0,
            r1: 1.0,
            open: false,
        };
        // Side hit from the x direction at z = 0.5.
        let t = hit(&cyl, &Ray::new(DVec3::new(-5.0, 0.0, 0.5), DVec3::X)).unwrap();
        assert!((t - 4.0).abs() < 1e-12);
        // Cap hit from below.
        let ray = Ray::new(DVec3::new(0.2, 0.0, -3.0), DVec3::Z);
        let t = hit(&cyl, &ray).unwrap();
        assert!((t - 3.0).abs() < 1e-12);
        assert_eq!(cyl.normal(ray.at(t), &no_tables()), -DVec3::Z);
        let open = ShapeKind::Cone {
            r0: 1.0,
            r1: 1.0,
            open: true,
        };
        assert!((hit(&open, &ray)).is_none());
        let cone = ShapeKind::Cone {
            r0: 1.0,
            r1: 0.0,
            open: false,
        };
        // At z = 0.5 the radius is 0.5.
        let t = hit(&cone, &Ray::new(DVec3::new(-5.0, 0.0, 0.5), DVec3::X)).unwrap();
        assert!((t - 4.5).abs() < 1e-12);
        let disc = ShapeKind::Disc {
            radius: 2.0,
            hole: 1.0,
        };
        assert!(hit(&disc, &Ray::new(DVec3::new(0.5, 0.0, -1.0), DVec3::Z)).is_none());
        assert_eq!(
            hit(&disc, &Ray::new(DVec3::new(1.5, 0.0, -1.0), DVec3::Z)),
            Some(1.0)
        );
    }

    #[test]
    fn torus_four_hits_along_its_diameter() {
        let torus = ShapeKind::Torus {
            major: 2.0,
            minor: 0.5,
        };
        let r = torus.all_hits(
            &Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X),
            &no_tables(),
        );
        assert_eq!(r.len, 4);
        for (got, want) in r.as_slice().iter().zip([7.5, 8.5, 11.5, 12.5]) {
            assert!((got - want).abs() < 1e-9, "{got} vs {want}");
        }
        // Far away and with a scaled direction.
        let r = torus.all_hits(
            &Ray::new(DVec3::new(-1e6, 0.0, 0.0), DVec3::X * 2.0),
            &no_tables(),
        );
        assert_eq!(r.len, 4);
        assert!((r.values[0] - (1e6 - 2.5) / 2.0).abs() < 1e-6);
        assert!(torus.inside(DVec3::new(2.0, 0.0, 0.0), &no_tables()));
        assert!(!torus.inside(DVec3::ZERO, &no_tables()));
    }

    /// The torus's first hit in (0, t_max) is the first of all its crossings there, bit for
    /// bit, for rays from outside and from its surface, with t_max before, between and after
    /// the crossings.
    #[test]
    fn torus_first_hit_is_the_first_of_its_crossings() {
        let (major, minor) = (2.0, 0.5);
        let torus = ShapeKind::Torus { major, minor };
        let mut next = crate::geometry::uniform_stream(23);
        let mut v = |s: f64| DVec3::new(next(), next(), next()) * 2.0 * s - DVec3::splat(s);
        let mut hits = 0;
        for k in 0..4000 {
            let origin = v(6.0);
            let dir = v(2.5) * DVec3::new(1.0, 0.3, 1.0) - origin;
            let mut ray = Ray::new(origin, dir);
            let all = torus.all_hits(&ray, &no_tables());
            if k % 2 == 1 && all.len > 0 {
                // From the first crossing, as a shadow or reflected ray leaves the surface.
                ray = Ray::new(ray.at(all.values[0]), dir);
            }
            hits += first_hit_is_first_crossing(&torus, &ray, &no_tables(), [0.3, 0.6, 0.9]);
        }
        assert!(hits > 3000, "{hits} hits");
    }

    /// Asserts that `shape`'s first hit along `ray` before each of `t_max` and infinity is
    /// the first of its crossings there; how many of those hits there were.
    fn first_hit_is_first_crossing(
        shape: &ShapeKind,
        ray: &Ray,
        tables: &ShapeTables,
        t_max: [f64; 3],
    ) -> usize {
        let all = shape.all_hits(ray, tables);
        let mut hits = 0;
        for t_max in t_max.into_iter().chain([f64::INFINITY]) {
            let want = all
                .as_slice()
                .iter()
                .copied()
                .find(|&t| t > 0.0 && t < t_max);
            assert_eq!(shape.intersect(ray, t_max, tables), want, "{ray:?}");
            hits += usize::from(want.is_some());
        }
        hits
    }

    /// Every crossing of a torus is found, the bounds' shortcut included: the roots of
    /// random rays (from outside and inside the bounds, aimed near the torus, directions of
    /// any length) against the sign changes of the torus's implicit function sampled
    /// densely along them.
    #[test]
    fn torus_roots_are_its_crossings() {
        use rand::{RngExt, SeedableRng};
        let (major, minor) = (2.0, 0.5);
        let torus = ShapeKind::Torus { major, minor };
        let g = |p: DVec3| {
            let k = p.dot(p) + major * major - minor * minor;
            k * k - 4.0 * major * major * (p.x * p.x + p.z * p.z)
        };
        let mut rng = rand_pcg::Pcg64::seed_from_u64(16);
        let (mut checked, mut crossings) = (0, 0);
        for _ in 0..4000 {
            let mut v = |s: f64| {
                DVec3::new(
                    rng.random_range(-s..s),
                    rng.random_range(-s..s),
                    rng.random_range(-s..s),
                )
            };
            let origin = v(6.0);
            let target = v(2.5) * DVec3::new(1.0, 0.3, 1.0);
            let dir = (target - origin) * rng.random_range(0.3..3.0);
            let roots = torus.all_hits(&Ray::new(origin, dir), &no_tables());
            let steps = 20_000;
            let t_end = 20.0 / dir.length();
            let dt = t_end / f64::from(steps);
            let found: Vec<f64> = roots
                .as_slice()
                .iter()
                .copied()
                .filter(|&t| t > dt && t < t_end)
                .collect();
            // Two crossings within a few steps (a grazing ray) would hide from the sampling.
            if found.windows(2).any(|w| w[1] - w[0] < 4.0 * dt) {
                continue;
            }
            let mut changes = 0;
            let mut last = g(origin + dir * dt);
            for i in 2..=steps {
                let now = g(origin + dir * (dt * f64::from(i)));
                if (now < 0.0) != (last < 0.0) {
                    changes += 1;
                }
                last = now;
            }
            assert_eq!(
                found.len(),
                changes,
                "origin {origin} dir {dir}: roots {found:?}"
            );
            for &t in &found {
                let p = origin + dir * t;
                assert!(
                    g(p).abs() < 1e-6 * (1.0 + p.length_squared().powi(2)),
                    "{t}: {}",
                    g(p)
                );
            }
            checked += 1;
            crossings += changes;
        }
        assert!(
            checked > 3500 && crossings > 2000,
            "{checked} rays, {crossings} crossings"
        );
    }

    #[test]
    fn quadric_as_a_sphere() {
        let tables = ShapeTables {
            quadrics: vec![[1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]],
            ..ShapeTables::default()
        };
        let q = ShapeKind::Quadric(0);
        let t = q.intersect(
            &Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z),
            f64::INFINITY,
            &tables,
        );
        assert_eq!(t, Some(4.0));
        assert!(q.inside(DVec3::ZERO, &tables));
    }

    /// The slab x^2 = h^2 as a quartic, and a ray along x from a point on its face x = -h.
    fn slab_hit_from_its_face(h: f64, dir: DVec3) -> Option<f64> {
        let mut q = [0.0; 35];
        q[9] = 1.0;
        q[34] = -h * h;
        let tables = ShapeTables {
            quartics: vec![q],
            ..ShapeTables::default()
        };
        let ray = Ray::new(DVec3::new(-h * (1.0 + 1e-9), 0.3, 0.0), dir);
        ShapeKind::Quartic(0).intersect(&ray, f64::INFINITY, &tables)
    }

    /// A quartic's first hit in (0, t_max) is the first of all its crossings there, bit for
    /// bit: random quartics (every coefficient in [-1, 1]), random rays, four t_max.
    #[test]
    fn quartic_first_hit_is_the_first_of_its_crossings() {
        let mut next = crate::geometry::uniform_stream(31);
        let mut hits = 0;
        for _ in 0..400 {
            let tables = ShapeTables {
                quartics: vec![std::array::from_fn(|_| 2.0 * next() - 1.0)],
                ..ShapeTables::default()
            };
            let quartic = ShapeKind::Quartic(0);
            for _ in 0..10 {
                let mut v = || DVec3::new(next(), next(), next()) * 4.0 - DVec3::splat(2.0);
                let ray = Ray::new(v(), v());
                hits += first_hit_is_first_crossing(&quartic, &ray, &tables, [0.2, 0.5, 1.0]);
            }
        }
        assert!(hits > 1000, "{hits} hits");
    }

    /// The polynomial along a ray is the quartic at the ray's points: sparse random
    /// quartics (half the coefficients 0, so that terms without x, y or z, whose products
    /// are skipped, are common), random rays, five distances.
    #[test]
    fn quartic_along_a_ray_is_the_quartic_at_its_points() {
        let mut next = crate::geometry::uniform_stream(47);
        for _ in 0..300 {
            let q: [f64; 35] = std::array::from_fn(|_| {
                if next() < 0.5 {
                    0.0
                } else {
                    2.0 * next() - 1.0
                }
            });
            let mut v = || DVec3::new(next(), next(), next()) * 4.0 - DVec3::splat(2.0);
            let ray = Ray::new(v(), v());
            let coef = quartic_along(&ray, &q);
            for t in [-1.5, -0.2, 0.0, 0.7, 2.0] {
                let along = coef.iter().fold(0.0, |acc, c| acc * t + c);
                let at = quartic_value(&q, ray.origin + ray.direction * t);
                // Both sum terms of size up to 35 * (|o| + |t d|)^4.
                let scale = (ray.origin.length() + t.abs() * ray.direction.length()).powi(4);
                assert!(
                    (along - at).abs() <= 1e-12 * 35.0 * (1.0 + scale),
                    "{along} vs {at}"
                );
            }
        }
    }

    #[test]
    fn a_ray_leaving_a_quartic_ignores_its_own_surface() {
        // The far face 2e-4 away is found, in the quartic's units whatever the direction's
        // length; 5e-5 is within POV-Ray's tolerance, like the face the ray starts on.
        for len in [1.0, 3.0] {
            let t = slab_hit_from_its_face(1e-4, DVec3::X * len).unwrap();
            assert!((t * len - 2e-4).abs() < 1e-9, "{t}");
            assert_eq!(slab_hit_from_its_face(2.5e-5, DVec3::X * len), None);
        }
    }

    #[test]
    fn triangles_and_polygons() {
        let tables = ShapeTables {
            triangles: vec![TriangleData {
                p0: DVec3::ZERO,
                e1: DVec3::X,
                e2: DVec3::Y,
                normals: Some([DVec3::Z, DVec3::Z, DVec3::X]),
            }],
            polygons: vec![PolygonData {
                // A square with a square hole.
                points: vec![
                    DVec2::new(0.0, 0.0),
                    DVec2::new(4.0, 0.0),
                    DVec2::new(4.0, 4.0),
                    DVec2::new(0.0, 4.0),
                    DVec2::new(1.0, 1.0),
                    DVec2::new(3.0, 1.0),
                    DVec2::new(3.0, 3.0),
                    DVec2::new(1.0, 3.0),
                ],
                loops: vec![(0, 4), (4, 8)],
                bounds: (DVec2::ZERO, DVec2::splat(4.0)),
            }],
            ..ShapeTables::default()
        };
        let tri = ShapeKind::Triangle(0);
        let ray = Ray::new(DVec3::new(0.25, 0.25, -1.0), DVec3::Z);
        assert_eq!(tri.intersect(&ray, f64::INFINITY, &tables), Some(1.0));
        assert!(
            tri.intersect(
                &Ray::new(DVec3::new(0.75, 0.75, -1.0), DVec3::Z),
                f64::INFINITY,
                &tables
            )
            .is_none()
        );
        let (_, n) = tri.normals(DVec3::new(0.0, 0.5, 0.0), 0, &tables);
        assert!((n - DVec3::new(0.5, 0.0, 0.5)).length() < 1e-12, "{n}");
        let poly = ShapeKind::Polygon(0);
        let through = |x: f64, y: f64| {
            poly.intersect(
                &Ray::new(DVec3::new(x, y, -1.0), DVec3::Z),
                f64::INFINITY,
                &tables,
            )
        };
        assert_eq!(through(0.5, 0.5), Some(1.0));
        assert_eq!(through(2.0, 2.0), None);
        assert_eq!(through(5.0, 2.0), None);
    }

    /// The convex solids' spans along a line hold every point of the line inside them,
    /// and points well within a span are inside; non-convex quadrics give no span.
    #[test]
    fn line_inside_is_where_the_line_is_inside() {
        let mut next = crate::geometry::uniform_stream(0x2545_f491_4f6c_dd1d);
        let mut v = |s: f64| DVec3::new(next(), next(), next()) * (2.0 * s) - s;
        let tables = ShapeTables {
            quadrics: vec![
                [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
                [1.0, 0.5, 2.0, 0.0, 0.0, 0.0, 0.4, 0.0, -0.3, -1.5],
                [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0],
                [1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
            ],
            ..ShapeTables::default()
        };
        let shapes = [
            sphere(DVec3::new(0.3, -0.2, 0.1), 1.3),
            ShapeKind::Plane {
                normal: DVec3::new(0.6, 0.0, 0.8),
                distance: 0.4,
            },
            ShapeKind::Box {
                min: DVec3::new(-1.0, -0.5, -2.0),
                max: DVec3::new(1.5, 0.5, 1.0),
            },
            ShapeKind::Quadric(0),
            ShapeKind::Quadric(1),
            ShapeKind::Quadric(2),
        ];
        assert_eq!(
            ShapeKind::Quadric(3).line_inside(&Ray::new(DVec3::ZERO, DVec3::X), &tables),
            LineInside::Unknown
        );
        let mut inside_points = 0;
        for shape in &shapes {
            for _ in 0..2000 {
                let ray = Ray::new(v(4.0), v(1.0));
                let span = shape.line_inside(&ray, &tables);
                for k in 0..50 {
                    let t = -8.0 + 0.33 * f64::from(k);
                    let p = ray.at(t);
                    let within = |margin: f64| match span {
                        LineInside::Between(a, b) => t > a - margin && t < b + margin,
                        LineInside::Never => false,
                        LineInside::Unknown => panic!("{shape:?} has a span"),
                    };
                    if shape.inside(p, &tables) {
                        inside_points += 1;
                        assert!(within(1e-9), "{shape:?} {ray:?} t {t}: {span:?}");
                    } else {
                        assert!(!within(-1e-6), "{shape:?} {ray:?} t {t}: {span:?}");
                    }
                }
            }
        }
        assert!(inside_points > 50_000, "{inside_points}");
    }

    /// A quadric's and a half-space's extents hold every point of their solid, and a
    /// cylinder's is open along its axis only.
    #[test]
    fn extents_hold_their_solids() {
        let mut next = crate::geometry::uniform_stream(0x9e37_79b9_7f4a_7c15);
        let tables = ShapeTables {
            quadrics: vec![
                [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -4.0],
                [2.0, 0.5, 3.0, 0.0, 0.0, 0.0, 1.0, -0.4, 0.3, -1.0],
                [1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
            ],
            ..ShapeTables::default()
        };
        let cylinder = ShapeKind::Quadric(0).extent(&tables);
        assert_eq!((cylinder.min.x, cylinder.max.y), (-2.0 - 3e-9, 2.0 + 3e-9));
        assert!(cylinder.min.z.is_infinite() && cylinder.max.z.is_infinite());
        assert_eq!(ShapeKind::Quadric(2).extent(&tables), Aabb::INFINITE);
        let half = ShapeKind::Plane {
            normal: DVec3::new(0.0, -1.0, 0.0),
            distance: 0.5,
        };
        let slanted = ShapeKind::Plane {
            normal: DVec3::new(0.0, 0.6, 0.8),
            distance: 0.5,
        };
        assert_eq!(slanted.extent(&tables), Aabb::INFINITE);
        let mut held = 0;
        for shape in [ShapeKind::Quadric(0), ShapeKind::Quadric(1), half] {
            let extent = shape.extent(&tables);
            for _ in 0..20_000 {
                let p = DVec3::new(next(), next(), next()) * 8.0 - 4.0;
                if shape.inside(p, &tables) {
                    held += 1;
                    assert!(
                        p.cmpge(extent.min).all() && p.cmple(extent.max).all(),
                        "{shape:?}: {p} outside {extent:?}"
                    );
                }
            }
        }
        assert!(held > 15_000, "{held}");
    }
}
