//! `mesh_camera`: primary rays from the faces of meshes. Measured with POV-Ray 3.7 on meshes
//! of small numbered triangles in front of emitting planes whose colour encodes the hit
//! point, one ray per pixel (`-A`):
//! - A face's ray starts at its centroid and goes along (c - a) x (b - a) for corners a, b, c
//!   (against it when the camera's `direction` has a negative z); `location`'s z moves the
//!   start along that same (unreversed) normal. With `smooth`, the corner normals are
//!   interpolated (at the centroid, or at the uv point of type 3).
//! - The image's rows index the faces from its second row: pixel (x, y) reads face
//!   `(max(y, 1) - 1) * width + x`, so the top row repeats the second. A pixel without a face
//!   is black, not the background.
//! - Type 0: ray r of a pixel comes from mesh r (rays_per_pixel <= meshes); the pixel is the
//!   mean of the rays that have a face.
//! - Type 1: the meshes' faces in one list. With rays_per_pixel > 1, POV-Ray 3.7's image is
//!   the one of a single ray per pixel (the further rays its documentation describes do not
//!   show), so penumbra shoots one.
//! - Type 2: columns of width `width / meshes` (rounded down), mesh `min(x / columns,
//!   meshes - 1)`; the face index is `row * columns + x` with x counted from the image's left
//!   edge, not the column's.
//! - Type 3: the point (u, v) = (x / width, 1 - y / height) of the image, found in the faces'
//!   uv triangles; the ray starts at the matching point of the face. POV-Ray samples it at
//!   the pixel's corner, so its converged (supersampled) image is the pixel's area, which is
//!   what penumbra samples.
//! - `max_distance`: beyond it a camera ray sees the background.
//!
//! The side tables (face starts, a uv grid) are built once per render; a ray costs no
//! allocation.

use glam::DVec2;

use crate::geometry::Ray;
use crate::scene::{CameraFace, MeshDistribution, MeshView};

/// The finest uv grid: cells per side.
const MAX_GRID: usize = 512;
/// How far outside a uv triangle a point still counts as inside (shared edges).
const UV_EPSILON: f64 = 1e-9;

/// A mesh camera ready to shoot rays.
#[derive(Clone, Debug)]
pub struct MeshCameraRays {
    view: MeshView,
    /// Per mesh, the index of its first face in the summed list (type 1), and the total last.
    starts: Vec<usize>,
    /// Type 3: a `grid` x `grid` table over uv [0, 1]^2 of the faces each cell touches, as
    /// (mesh, face) pairs in `cell_faces[cell_start[c]..cell_start[c + 1]]`.
    grid: usize,
    cell_start: Vec<u32>,
    cell_faces: Vec<(u32, u32)>,
}

impl MeshCameraRays {
    pub fn new(view: &MeshView) -> MeshCameraRays {
        let rig = &view.rig;
        let mut starts = Vec::with_capacity(rig.meshes.len() + 1);
        let mut total = 0;
        for m in &rig.meshes {
            starts.push(total);
            total += m.faces.len();
        }
        starts.push(total);
        let mut rays = MeshCameraRays {
            view: view.clone(),
            starts,
            grid: 0,
            cell_start: Vec::new(),
            cell_faces: Vec::new(),
        };
        if rig.distribution == MeshDistribution::UvMapped {
            rays.build_grid(total);
        }
        rays
    }

    fn build_grid(&mut self, faces: usize) {
        let grid = ((faces as f64).sqrt().ceil() as usize).clamp(1, MAX_GRID);
        let cell = |t: f64| ((t * grid as f64).floor().max(0.0) as usize).min(grid - 1);
        let mut lists: Vec<Vec<(u32, u32)>> = vec![Vec::new(); grid * grid];
        for (mi, m) in self.view.rig.meshes.iter().enumerate() {
            for (fi, f) in m.faces.iter().enumerate() {
                let Some(uv) = f.uvs else { continue };
                let lo = uv[0].min(uv[1]).min(uv[2]);
                let hi = uv[0].max(uv[1]).max(uv[2]);
                if hi.x < 0.0 || hi.y < 0.0 || lo.x > 1.0 || lo.y > 1.0 {
                    continue;
                }
                for cy in cell(lo.y)..=cell(hi.y) {
                    for cx in cell(lo.x)..=cell(hi.x) {
                        lists[cy * grid + cx].push((mi as u32, fi as u32));
                    }
                }
            }
        }
        self.grid = grid;
        self.cell_start = Vec::with_capacity(grid * grid + 1);
        let mut n = 0u32;
        for l in &lists {
            self.cell_start.push(n);
            n += l.len() as u32;
        }
        self.cell_start.push(n);
        self.cell_faces = lists.into_iter().flatten().collect();
    }

    /// The ray of pixel (x, y) of a w x h image for the sample whose pixel position is
    /// `pick` in [0, 1)^2: type 3 reads it as the point in the pixel, type 0 as the choice
    /// among the pixel's rays. `None`: no face, a black pixel.
    pub fn ray(&self, (x, y, w, h): (usize, usize, usize, usize), pick: (f64, f64)) -> Option<Ray> {
        let rig = &self.view.rig;
        let row = y.max(1) - 1;
        let pixel = row * w + x;
        let face = match rig.distribution {
            MeshDistribution::PerMesh => {
                let rays = (rig.rays_per_pixel as usize).min(rig.meshes.len());
                let has = |r: usize| pixel < rig.meshes[r].faces.len();
                let shot = (0..rays).filter(|&r| has(r)).count();
                if shot == 0 {
                    return None;
                }
                let k = ((pick.0 * shot as f64) as usize).min(shot - 1);
                let r = (0..rays).filter(|&r| has(r)).nth(k)?;
                rig.meshes[r].faces[pixel]
            }
            MeshDistribution::Summed => {
                let m = self
                    .starts
                    .partition_point(|&s| s <= pixel)
                    .checked_sub(1)?;
                *rig.meshes.get(m)?.faces.get(pixel - self.starts[m])?
            }
            MeshDistribution::SideBySide => {
                let n = rig.meshes.len();
                let columns = w / n;
                if columns == 0 {
                    return None;
                }
                let m = (x / columns).min(n - 1);
                *rig.meshes[m].faces.get(row * columns + x)?
            }
            MeshDistribution::UvMapped => {
                let u = (x as f64 + pick.0) / w as f64;
                let v = 1.0 - (y as f64 + pick.1) / h as f64;
                let (face, weights) = self.uv_face(DVec2::new(u, v))?;
                return Some(self.face_ray(&face, weights));
            }
        };
        Some(self.face_ray(&face, [1.0 / 3.0; 3]))
    }

    fn face_ray(&self, face: &CameraFace, weights: [f64; 3]) -> Ray {
        let (p, n) = face.at(weights, self.view.rig.smooth);
        let origin = p + n * self.view.offset;
        Ray::new(origin, if self.view.reverse { -n } else { n })
    }

    /// The first face (in mesh order) whose uv triangle holds `uv`, and the weights of its
    /// corners there.
    fn uv_face(&self, uv: DVec2) -> Option<(CameraFace, [f64; 3])> {
        if self.grid == 0 || !(0.0..=1.0).contains(&uv.x) || !(0.0..=1.0).contains(&uv.y) {
            return None;
        }
        let g = self.grid;
        let cell = |t: f64| ((t * g as f64) as usize).min(g - 1);
        let c = cell(uv.y) * g + cell(uv.x);
        let list = &self.cell_faces[self.cell_start[c] as usize..self.cell_start[c + 1] as usize];
        list.iter()
            .filter_map(|&(m, f)| {
                let face = self.view.rig.meshes[m as usize].faces[f as usize];
                let w = barycentric(face.uvs?, uv)?;
                Some(((m, f), face, w))
            })
            .min_by_key(|(key, _, _)| *key)
            .map(|(_, face, w)| (face, w))
    }
}

/// The weights of `p` in the 2-D triangle `t`, if it lies inside (or on an edge).
fn barycentric(t: [DVec2; 3], p: DVec2) -> Option<[f64; 3]> {
    let (e1, e2, d) = (t[1] - t[0], t[2] - t[0], p - t[0]);
    let det = e1.perp_dot(e2);
    if det.abs() < 1e-300 {
        return None;
    }
    let wb = d.perp_dot(e2) / det;
    let wc = e1.perp_dot(d) / det;
    let wa = 1.0 - wb - wc;
    (wa >= -UV_EPSILON && wb >= -UV_EPSILON && wc >= -UV_EPSILON).then_some([wa, wb, wc])
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use glam::DVec3;

    use super::*;
    use crate::scene::{CameraMesh, MeshCamera};

    /// Face i: a small triangle at x = i, its ray along -z.
    fn strip(n: usize, x0: f64) -> CameraMesh {
        CameraMesh {
            faces: (0..n)
                .map(|i| {
                    let a = DVec3::new(x0 + i as f64, 0.0, 0.0);
                    CameraFace {
                        corners: [a, a + DVec3::X * 0.5, a + DVec3::Y * 0.5],
                        normals: None,
                        uvs: None,
                    }
                })
                .collect(),
        }
    }

    fn rays(distribution: MeshDistribution, rays: u32, meshes: Vec<CameraMesh>) -> MeshCameraRays {
        MeshCameraRays::new(&MeshView {
            rig: Arc::new(MeshCamera {
                rays_per_pixel: rays,
                distribution,
                max_distance: None,
                meshes,
                smooth: false,
            }),
            offset: 0.0,
            reverse: false,
        })
    }

    /// The face a ray came from: its centroid's x, rounded down.
    fn face_of(r: &MeshCameraRays, px: (usize, usize, usize, usize), pick: f64) -> Option<i64> {
        r.ray(px, (pick, 0.5))
            .map(|ray| ray.origin.x.floor() as i64)
    }

    #[test]
    fn type_0_maps_faces_to_pixels_from_the_second_row() {
        // Measured (4 x 4, 5 faces): rows 0 and 1 show faces 0..3, row 2 face 4, the rest
        // black.
        let r = rays(MeshDistribution::PerMesh, 1, vec![strip(5, 0.0)]);
        let at = |x, y| face_of(&r, (x, y, 4, 4), 0.5);
        assert_eq!(
            [at(0, 0), at(3, 0), at(0, 1), at(3, 1)],
            [Some(0), Some(3), Some(0), Some(3)]
        );
        assert_eq!(at(0, 2), Some(4));
        assert_eq!(at(1, 2), None);
        assert_eq!(at(0, 3), None);
        let ray = r.ray((1, 1, 4, 4), (0.5, 0.5)).expect("a face");
        assert!((ray.origin - DVec3::new(1.0 + 1.0 / 6.0, 1.0 / 6.0, 0.0)).length() < 1e-12);
        assert!(
            (ray.direction + DVec3::Z).length() < 1e-12,
            "{:?}",
            ray.direction
        );
    }

    #[test]
    fn type_0_averages_the_meshes_that_have_the_face() {
        // Two rays: mesh 0 (8 faces) and mesh 1 (3 faces, at x = 16..). Pixel 0 mixes both;
        // pixel 5 only has mesh 0's face.
        let r = rays(
            MeshDistribution::PerMesh,
            2,
            vec![strip(8, 0.0), strip(3, 16.0)],
        );
        assert_eq!(face_of(&r, (0, 1, 4, 4), 0.2), Some(0));
        assert_eq!(face_of(&r, (0, 1, 4, 4), 0.7), Some(16));
        assert_eq!(face_of(&r, (1, 2, 4, 4), 0.2), Some(5));
        assert_eq!(face_of(&r, (1, 2, 4, 4), 0.7), Some(5));
    }

    #[test]
    fn type_1_sums_and_type_2_splits_the_image() {
        let r = rays(
            MeshDistribution::Summed,
            1,
            vec![strip(10, 0.0), strip(8, 16.0)],
        );
        assert_eq!(
            face_of(&r, (2, 3, 4, 4), 0.5),
            Some(16),
            "pixel 10: mesh 1's face 0"
        );
        assert_eq!(face_of(&r, (1, 3, 4, 4), 0.5), Some(9));
        // Measured at 5 x 4 with two meshes: columns of 2, the face index counts x from the
        // image's left edge.
        let r = rays(
            MeshDistribution::SideBySide,
            1,
            vec![strip(10, 0.0), strip(8, 16.0)],
        );
        assert_eq!(face_of(&r, (1, 2, 5, 4), 0.5), Some(3));
        assert_eq!(face_of(&r, (2, 0, 5, 4), 0.5), Some(18));
        assert_eq!(face_of(&r, (4, 2, 5, 4), 0.5), Some(22));
        assert_eq!(face_of(&r, (4, 3, 5, 4), 0.5), None);
    }

    #[test]
    fn type_3_finds_the_pixel_in_the_uv_map() {
        // One triangle over the lower-left half of uv space, 16 units on a side: the ray
        // starts at (16 u, 16 v).
        let face = CameraFace {
            corners: [DVec3::ZERO, DVec3::X * 16.0, DVec3::Y * 16.0],
            normals: None,
            uvs: Some([DVec2::ZERO, DVec2::X, DVec2::Y]),
        };
        let r = rays(
            MeshDistribution::UvMapped,
            1,
            vec![CameraMesh { faces: vec![face] }],
        );
        let ray = r.ray((1, 2, 4, 4), (0.25, 0.5)).expect("inside");
        // u = (1 + 0.25) / 4, v = 1 - (2 + 0.5) / 4.
        assert!(
            (ray.origin - DVec3::new(5.0, 6.0, 0.0)).length() < 1e-9,
            "{:?}",
            ray.origin
        );
        assert!(
            r.ray((3, 0, 4, 4), (0.5, 0.5)).is_none(),
            "outside the triangle"
        );
    }

    #[test]
    fn location_and_direction_move_and_turn_the_ray() {
        let mut r = rays(MeshDistribution::PerMesh, 1, vec![strip(1, 0.0)]);
        r.view.offset = 1.0;
        r.view.reverse = true;
        let ray = r.ray((0, 0, 1, 1), (0.5, 0.5)).expect("a face");
        // Measured: the start moves along the face's normal (-z here), the direction turns.
        assert!((ray.origin.z + 1.0).abs() < 1e-12);
        assert!((ray.direction - DVec3::Z).length() < 1e-12);
    }
}
