//! Triangle meshes (`mesh`, `mesh2`, tessellated bicubic patches) as one primitive with its
//! own BVH. Vertices, normals and uvs are shared arrays indexed by the faces, in single
//! precision as POV-Ray stores them: a large mesh costs a few tens of bytes per triangle
//! instead of a primitive, a material and a world-space copy of each.

use glam::{DVec2, DVec3};

use super::{Aabb, Bvh, Ray};

/// "No index": a flat corner normal, a face without uvs, the mesh's own texture.
pub const NONE: u32 = u32::MAX;

#[derive(Clone, Debug, Default)]
pub struct MeshData {
    pub vertices: Vec<[f32; 3]>,
    pub normals: Vec<[f32; 3]>,
    pub uvs: Vec<[f32; 2]>,
    pub faces: Vec<[u32; 3]>,
    /// Per face, its corners' normals (`NONE` for a flat face); empty when no face is smooth.
    pub face_normals: Vec<[u32; 3]>,
    /// Per face, its corners' uvs; empty when the mesh has none.
    pub face_uvs: Vec<[u32; 3]>,
    /// Per face, its corners' texture slots (`NONE`: the mesh's own texture); empty when
    /// every face shows the mesh's texture.
    pub face_textures: Vec<[u32; 3]>,
    /// The material of each texture slot, filled when the scene is prepared.
    pub materials: Vec<u32>,
    /// Direction of the parity ray of the inside test; without it nothing is inside.
    pub inside_vector: Option<DVec3>,
    bvh: Bvh,
    bounds: Aabb,
}

impl MeshData {
    /// Builds the BVH over the faces and puts the faces in its leaf order, so the faces a
    /// ray tests one after another are neighbours in memory.
    pub fn finish(&mut self) {
        let boxes: Vec<Aabb> = self.faces.iter().map(|f| self.face_bounds(f)).collect();
        self.bounds = boxes.iter().fold(Aabb::EMPTY, |a, b| a.union(b));
        let mut bvh = Bvh::build(&boxes);
        let order = std::mem::take(&mut bvh.items);
        let permute = |v: &mut Vec<[u32; 3]>| {
            if !v.is_empty() {
                *v = order.iter().map(|&i| v[i as usize]).collect();
            }
        };
        permute(&mut self.faces);
        permute(&mut self.face_normals);
        permute(&mut self.face_uvs);
        permute(&mut self.face_textures);
        bvh.items_in_leaf_order();
        // The build reserves room for the worst case; a mesh keeps what it used.
        bvh.nodes.shrink_to_fit();
        self.bvh = bvh;
    }

    fn face_bounds(&self, f: &[u32; 3]) -> Aabb {
        let [a, b, c] = f.map(|i| self.vertex(i));
        Aabb::new(a, b).grow(c)
    }

    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    pub fn memory_bytes(&self) -> usize {
        self.vertices.capacity() * 12
            + self.normals.capacity() * 12
            + self.uvs.capacity() * 8
            + (self.faces.capacity()
                + self.face_normals.capacity()
                + self.face_uvs.capacity()
                + self.face_textures.capacity())
                * 12
            + self.materials.capacity() * 4
            + self.bvh.nodes.capacity() * std::mem::size_of::<super::bvh::Node>()
            + self.bvh.items.capacity() * 4
    }

    #[inline]
    fn vertex(&self, i: u32) -> DVec3 {
        let v = self.vertices[i as usize];
        DVec3::new(v[0] as f64, v[1] as f64, v[2] as f64)
    }

    /// The nearest hit in (0, t_max) and the face it is on.
    #[inline]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<(f64, u32)> {
        let mut best = None;
        self.bvh
            .traverse(ray, t_max, |face, t_cur| match self.face_hit(ray, face) {
                Some(t) if t > 0.0 && t < t_cur => {
                    best = Some((t, face));
                    Some(t)
                }
                _ => Some(t_cur),
            });
        best
    }

    /// Every crossing ahead of the ray's origin, with its face, in no particular order.
    pub fn each_hit(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        self.bvh.traverse(ray, f64::INFINITY, |face, t_cur| {
            if let Some(t) = self.face_hit(ray, face)
                && t > 0.0
            {
                f(t, face);
            }
            Some(t_cur)
        });
    }

    /// Möller-Trumbore, edges included, so that a ray through a shared edge meets a face.
    #[inline]
    fn face_hit(&self, ray: &Ray, face: u32) -> Option<f64> {
        let [a, b, c] = self.faces[face as usize].map(|i| self.vertex(i));
        let (e1, e2) = (b - a, c - a);
        let p = ray.direction.cross(e2);
        let det = e1.dot(p);
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let inv = 1.0 / det;
        let s = ray.origin - a;
        let u = s.dot(p) * inv;
        if !(0.0..=1.0).contains(&u) {
            return None;
        }
        let q = s.cross(e1);
        let v = ray.direction.dot(q) * inv;
        if v < 0.0 || u + v > 1.0 {
            return None;
        }
        Some(e2.dot(q) * inv)
    }

    /// The face's corners and the barycentric weights of `p` on its plane.
    fn weights(&self, face: u32, p: DVec3) -> ([DVec3; 3], DVec3) {
        let corners = self.faces[face as usize].map(|i| self.vertex(i));
        let (e1, e2) = (corners[1] - corners[0], corners[2] - corners[0]);
        let n = e1.cross(e2);
        let nn = n.length_squared();
        if nn == 0.0 {
            return (corners, DVec3::new(1.0, 0.0, 0.0));
        }
        let w = p - corners[0];
        let u = w.cross(e2).dot(n) / nn;
        let v = e1.cross(w).dot(n) / nn;
        (corners, DVec3::new(1.0 - u - v, u, v))
    }

    /// The barycentric weights of a point on a face, for interpolating corner values.
    pub fn barycentric(&self, face: u32, p: DVec3) -> DVec3 {
        self.weights(face, p).1
    }

    pub fn normal(&self, face: u32) -> DVec3 {
        let [a, b, c] = self.faces[face as usize].map(|i| self.vertex(i));
        (b - a).cross(c - a)
    }

    /// The corner normals interpolated, where the face has them.
    pub fn shading_normal(&self, face: u32, p: DVec3) -> DVec3 {
        if let Some(&idx) = self.face_normals.get(face as usize)
            && idx[0] != NONE
        {
            let w = self.barycentric(face, p);
            let n = idx.map(|i| {
                let n = self.normals[i as usize];
                DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64)
            });
            let s = n[0] * w.x + n[1] * w.y + n[2] * w.z;
            if s.length_squared() > 0.0 {
                return s;
            }
        }
        self.normal(face)
    }

    /// The corner uvs interpolated (`uv_mapping`), where the mesh has them.
    pub fn uv(&self, face: u32, p: DVec3) -> Option<DVec2> {
        let idx = self.face_uvs.get(face as usize)?;
        if idx[0] == NONE {
            return None;
        }
        let w = self.barycentric(face, p);
        let uv = idx.map(|i| {
            let t = self.uvs[i as usize];
            DVec2::new(t[0] as f64, t[1] as f64)
        });
        Some(uv[0] * w.x + uv[1] * w.y + uv[2] * w.z)
    }

    /// The face's corner materials, or `None` when it shows the mesh's own (`own`).
    pub fn corner_materials(&self, face: u32, own: u32) -> Option<[u32; 3]> {
        let slots = self.face_textures.get(face as usize)?;
        Some(slots.map(|s| {
            if s == NONE {
                own
            } else {
                self.materials[s as usize]
            }
        }))
    }

    /// POV-Ray's inside test for meshes: an odd number of crossings along the inside
    /// vector from the point.
    pub fn inside(&self, p: DVec3) -> bool {
        let Some(v) = self.inside_vector else {
            return false;
        };
        let mut count = 0u32;
        self.each_hit(&Ray::new(p, v), |_, _| count += 1);
        count % 2 == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit cube of twelve faces around the origin.
    fn cube(inside_vector: Option<DVec3>) -> MeshData {
        let mut m = MeshData::default();
        for i in 0..8 {
            let s = |b: i32| if i & b == 0 { -0.5 } else { 0.5 };
            m.vertices.push([s(1), s(2), s(4)]);
        }
        let quads = [
            [0, 1, 3, 2],
            [4, 6, 7, 5],
            [0, 4, 5, 1],
            [2, 3, 7, 6],
            [0, 2, 6, 4],
            [1, 5, 7, 3],
        ];
        for q in quads {
            m.faces.push([q[0], q[1], q[2]]);
            m.faces.push([q[0], q[2], q[3]]);
        }
        m.inside_vector = inside_vector;
        m.finish();
        m
    }

    #[test]
    fn a_cube_is_hit_on_its_faces_and_has_an_inside_only_with_a_vector() {
        let m = cube(Some(DVec3::new(0.3, 1.0, 0.1)));
        let ray = Ray::new(DVec3::new(0.1, 0.2, -5.0), DVec3::Z);
        let (t, face) = m.hit(&ray, f64::INFINITY).unwrap();
        assert!((t - 4.5).abs() < 1e-9, "{t}");
        assert!(m.normal(face).z.abs() > 0.0);
        let mut n = 0;
        m.each_hit(&ray, |_, _| n += 1);
        assert_eq!(n, 2);
        assert!(m.inside(DVec3::new(0.1, 0.1, 0.1)));
        assert!(!m.inside(DVec3::new(0.1, 0.1, 1.1)));
        assert!(!cube(None).inside(DVec3::ZERO));
        let b = m.bounds();
        assert_eq!((b.min, b.max), (DVec3::splat(-0.5), DVec3::splat(0.5)));
    }
}
