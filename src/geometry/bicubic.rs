//! `bicubic_patch` as POV-Ray 3.7 renders it: the Bezier patch cut into 2^v_steps by
//! 2^u_steps sub-patches (halving the parameter range, so the cuts fall at even steps of u
//! and v), each shown as two triangles split along the diagonal from its (u0, v0) corner to
//! its (u1, v1) corner (measured on single sub-patches with one raised control point), with
//! normals from the patch's derivatives interpolated across them. POV-Ray's `v_steps`
//! cuts along a row of control points, where u (as `uv_mapping` reads it) runs, and
//! `u_steps` across the rows (measured on a patch curved one way only).

use glam::{DVec2, DVec3};

use super::mesh::MeshData;

/// At most this many halvings per direction (POV-Ray's own limit is about as deep).
pub const MAX_STEPS: u32 = 10;

/// The patch as a mesh: `points` row by row (index 4 v + u), `uv` the (u, v) of the
/// corners (0,0), (1,0), (1,1), (0,1) for `uv_mapping`; `along` and `across` the halvings
/// along and across the rows (POV-Ray's v_steps and u_steps).
pub fn tessellate(points: &[DVec3; 16], along: u32, across: u32, uv: [DVec2; 4]) -> MeshData {
    let nu = 1usize << along.min(MAX_STEPS);
    let nv = 1usize << across.min(MAX_STEPS);
    let mut m = MeshData::default();
    for j in 0..=nv {
        for i in 0..=nu {
            let (u, v) = (i as f64 / nu as f64, j as f64 / nv as f64);
            let (p, du, dv) = evaluate(points, u, v);
            m.vertices.push(p.as_vec3().to_array());
            let n = du.cross(dv);
            // A degenerate corner (coincident control points) has no normal of its own.
            let n = n.try_normalize().unwrap_or(DVec3::ZERO);
            m.normals.push(n.as_vec3().to_array());
            let bottom = uv[0].lerp(uv[1], u);
            let top = uv[3].lerp(uv[2], u);
            m.uvs.push(bottom.lerp(top, v).as_vec2().to_array());
        }
    }
    let at = |i: usize, j: usize| (j * (nu + 1) + i) as u32;
    for j in 0..nv {
        for i in 0..nu {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            for f in [[a, b, c], [a, c, d]] {
                if !degenerate(&m, f) {
                    m.faces.push(f);
                }
            }
        }
    }
    let smooth = m.normals.iter().all(|n| n != &[0.0; 3]);
    if smooth {
        m.face_normals = m.faces.clone();
    } else {
        m.normals.clear();
    }
    m.face_uvs = m.faces.clone();
    m
}

fn degenerate(m: &MeshData, f: [u32; 3]) -> bool {
    let [a, b, c] = f.map(|i| glam::Vec3::from_array(m.vertices[i as usize]).as_dvec3());
    (b - a).cross(c - a).length_squared() == 0.0
}

/// The cubic Bernstein weights at t and their derivatives.
fn bernstein(t: f64) -> ([f64; 4], [f64; 4]) {
    let s = 1.0 - t;
    (
        [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t],
        [
            -3.0 * s * s,
            3.0 * s * s - 6.0 * t * s,
            6.0 * t * s - 3.0 * t * t,
            3.0 * t * t,
        ],
    )
}

/// The point of the patch at (u, v) and its derivatives along u and v.
fn evaluate(points: &[DVec3; 16], u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
    let (bu, du) = bernstein(u);
    let (bv, dv) = bernstein(v);
    let (mut p, mut pu, mut pv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
    for j in 0..4 {
        for i in 0..4 {
            let c = points[4 * j + i];
            p += c * (bu[i] * bv[j]);
            pu += c * (du[i] * bv[j]);
            pv += c * (bu[i] * dv[j]);
        }
    }
    (p, pu, pv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_patch_tessellates_into_its_square() {
        let mut pts = [DVec3::ZERO; 16];
        for j in 0..4 {
            for i in 0..4 {
                pts[4 * j + i] = DVec3::new(i as f64 / 3.0, 0.0, j as f64 / 3.0);
            }
        }
        let uv = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ];
        let mut m = tessellate(&pts, 2, 1, uv);
        assert_eq!(m.faces.len(), 4 * 2 * 2);
        m.finish();
        let ray = crate::geometry::Ray::new(DVec3::new(0.3, 1.0, 0.6), -DVec3::Y);
        let (t, face) = m.hit(&ray, f64::INFINITY).unwrap();
        assert!((t - 1.0).abs() < 1e-6);
        let uv = m.uv(face, ray.at(t)).unwrap();
        assert!((uv - DVec2::new(0.3, 0.6)).length() < 1e-6, "{uv}");
        assert!(m.shading_normal(face, ray.at(t)).y.abs() > 0.99);
    }
}
