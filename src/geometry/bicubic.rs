//! `bicubic_patch` as POV-Ray 3.7 renders it: the Bezier patch cut into 2^v_steps by
//! 2^u_steps sub-patches (halving the parameter range, so the cuts fall at even steps of u
//! and v), each shown as two triangles split along the diagonal from its (u0, v0) corner to
//! its (u1, v1) corner (measured on single sub-patches with one raised control point), with
//! normals from the patch's derivatives interpolated across them. POV-Ray's `v_steps`
//! cuts along a row of control points, where u (as `uv_mapping` reads it) runs, and
//! `u_steps` across the rows (measured on a patch curved one way only).

use glam::{DAffine3, DVec2, DVec3};

use super::mesh::MeshData;

/// At most this many halvings per direction (POV-Ray's own limit is about as deep).
pub const MAX_STEPS: u32 = 10;

/// How a patch is cut: at most `along` halvings along the rows and `across` across them
/// (POV-Ray's v_steps and u_steps), stopping early where a piece is flat within `flatness`
/// once its control points are moved by `to_scene`.
#[derive(Clone, Copy, Debug)]
pub struct Subdivision {
    pub along: u32,
    pub across: u32,
    pub flatness: f64,
    pub to_scene: DAffine3,
}

/// A piece of the patch: its parameter ranges and its own control net.
#[derive(Clone, Copy)]
struct Piece {
    u: (f64, f64),
    v: (f64, f64),
    net: [DVec3; 16],
}

/// The patch as a mesh: `points` row by row (index 4 v + u), `uv` the (u, v) of the
/// corners (0,0), (1,0), (1,1), (0,1) for `uv_mapping`. Each piece shows as two triangles
/// through its corners on the surface; where neighbouring pieces stop at different depths
/// their edges need not meet, as in POV-Ray.
pub fn tessellate(points: &[DVec3; 16], cut: Subdivision, uv: [DVec2; 4]) -> MeshData {
    let mut leaves = Vec::new();
    let whole = Piece {
        u: (0.0, 1.0),
        v: (0.0, 1.0),
        net: *points,
    };
    let cut = Subdivision {
        along: cut.along.min(MAX_STEPS),
        across: cut.across.min(MAX_STEPS),
        ..cut
    };
    subdivide(whole, cut.along, cut.across, &cut, &mut leaves);
    let mut m = MeshData::default();
    for leaf in &leaves {
        let base = m.vertices.len() as u32;
        for (u, v) in [
            (leaf.u.0, leaf.v.0),
            (leaf.u.1, leaf.v.0),
            (leaf.u.1, leaf.v.1),
            (leaf.u.0, leaf.v.1),
        ] {
            let (p, du, dv) = evaluate(points, u, v);
            m.vertices.push(p.as_vec3().to_array());
            // A degenerate corner (coincident control points) has no normal of its own.
            let n = du.cross(dv).try_normalize().unwrap_or(DVec3::ZERO);
            m.normals.push(n.as_vec3().to_array());
            let bottom = uv[0].lerp(uv[1], u);
            let top = uv[3].lerp(uv[2], u);
            m.uvs.push(bottom.lerp(top, v).as_vec2().to_array());
        }
        let (a, b, c, d) = (base, base + 1, base + 2, base + 3);
        for f in [[a, b, c], [a, c, d]] {
            if !degenerate(&m, f) {
                m.faces.push(f);
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

/// Halves a piece in each direction that has halvings left, until it is flat enough.
fn subdivide(piece: Piece, along: u32, across: u32, cut: &Subdivision, out: &mut Vec<Piece>) {
    let done = along == 0 && across == 0;
    if done || (cut.flatness > 0.0 && flat_enough(&piece.net, cut)) {
        out.push(piece);
        return;
    }
    // Both ways at once while both have halvings left (four pieces), as the measured
    // facets of objects/bezier.pov need; then the one left.
    let halves: Vec<Piece> = match (along > 0, across > 0) {
        (true, true) => split(&piece, Axis::U)
            .iter()
            .flat_map(|h| split(h, Axis::V))
            .collect(),
        (true, false) => split(&piece, Axis::U).to_vec(),
        _ => split(&piece, Axis::V).to_vec(),
    };
    for half in halves {
        subdivide(
            half,
            along.saturating_sub(1),
            across.saturating_sub(1),
            cut,
            out,
        );
    }
}

/// Every control point, in the scene's units, within `flatness` of both planes through
/// three of the corners.
fn flat_enough(net: &[DVec3; 16], cut: &Subdivision) -> bool {
    let net = net.map(|p| cut.to_scene.transform_point3(p));
    let plane_holds = |a: DVec3, b: DVec3, c: DVec3| {
        let Some(n) = (b - a).cross(c - a).try_normalize() else {
            return true;
        };
        net.iter().all(|p| (*p - a).dot(n).abs() <= cut.flatness)
    };
    plane_holds(net[0], net[3], net[15]) && plane_holds(net[0], net[15], net[12])
}

/// De Casteljau at the middle of four control points: the two halves' points.
fn halve(p: [DVec3; 4]) -> ([DVec3; 4], [DVec3; 4]) {
    let m = |a: DVec3, b: DVec3| (a + b) * 0.5;
    let (p01, p12, p23) = (m(p[0], p[1]), m(p[1], p[2]), m(p[2], p[3]));
    let (p012, p123) = (m(p01, p12), m(p12, p23));
    let mid = m(p012, p123);
    ([p[0], p01, p012, mid], [mid, p123, p23, p[3]])
}

/// The parameter a piece is cut in: u along the rows, v across them.
#[derive(Clone, Copy, PartialEq)]
enum Axis {
    U,
    V,
}

/// The piece cut at the middle of `axis`.
fn split(piece: &Piece, axis: Axis) -> [Piece; 2] {
    // Control point k of line `line` along the axis.
    let at = |line: usize, k: usize| match axis {
        Axis::U => 4 * line + k,
        Axis::V => 4 * k + line,
    };
    let (mut lo, mut hi) = (piece.net, piece.net);
    for line in 0..4 {
        let (a, b) = halve([0, 1, 2, 3].map(|k| piece.net[at(line, k)]));
        for k in 0..4 {
            lo[at(line, k)] = a[k];
            hi[at(line, k)] = b[k];
        }
    }
    let range = if axis == Axis::U { piece.u } else { piece.v };
    let mid = 0.5 * (range.0 + range.1);
    let mut halves = [*piece, *piece];
    halves[0].net = lo;
    halves[1].net = hi;
    if axis == Axis::U {
        (halves[0].u, halves[1].u) = ((range.0, mid), (mid, range.1));
    } else {
        (halves[0].v, halves[1].v) = ((range.0, mid), (mid, range.1));
    }
    halves
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
        let mut m = tessellate(
            &pts,
            Subdivision {
                along: 2,
                across: 1,
                flatness: 0.0,
                to_scene: DAffine3::IDENTITY,
            },
            uv,
        );
        assert_eq!(m.faces.len(), 4 * 2 * 2);
        m.finish();
        let ray = crate::geometry::Ray::new(DVec3::new(0.3, 1.0, 0.6), -DVec3::Y);
        let (t, face) = m.hit(&ray, f64::INFINITY).unwrap();
        assert!((t - 1.0).abs() < 1e-6);
        let uv = m.uv(face, ray.at(t)).unwrap();
        assert!((uv - DVec2::new(0.3, 0.6)).length() < 1e-6, "{uv}");
        assert!(m.shading_normal(face, ray.at(t)).y.abs() > 0.99);
    }

    #[test]
    fn flatness_stops_the_cutting_in_the_scenes_units() {
        // A dome 1 high over a 3 x 3 square: cut until every piece's control points lie
        // within `flatness` of its corners' planes, measured after the object's transform.
        let mut pts = [DVec3::ZERO; 16];
        for j in 0..4 {
            for i in 0..4 {
                let inner = (1..3).contains(&i) && (1..3).contains(&j);
                pts[4 * j + i] = DVec3::new(i as f64, if inner { 1.0 } else { 0.0 }, j as f64);
            }
        }
        let uv = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
        let faces = |flatness: f64, scale: f64| {
            let cut = Subdivision {
                along: 6,
                across: 6,
                flatness,
                to_scene: DAffine3::from_scale(DVec3::splat(scale)),
            };
            tessellate(&pts, cut, uv).faces.len()
        };
        // Flat enough as it is: one piece, two triangles.
        assert_eq!(faces(2.0, 1.0), 2);
        // Not flat: cut, and more finely where the scene sees it 10 times larger.
        let (near, far) = (faces(0.05, 1.0), faces(0.05, 10.0));
        assert!(near > 2 && far > near, "{near} {far}");
        // Never past the steps: 2^6 x 2^6 pieces at most.
        assert!(faces(1e-9, 1.0) == 2 * 64 * 64);
    }
}
