use std::sync::Arc;

use glam::{DVec2, DVec3};

use super::{Normal, Transform};

/// A perspective camera in its final form: primary rays leave `location` along
/// `direction + x * right + y * up` with screen coordinates x, y in [-1/2, 1/2].
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    pub location: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    /// Focal blur: lens diameter (0: a pinhole) and the point that is in focus.
    pub aperture: f64,
    pub focal_point: DVec3,
    /// POV-Ray's `blur_samples`, which also sets the shape of its lens (src/render/camera.rs).
    pub blur_samples: u32,
    /// The `variance` of POV-Ray's rule for stopping a pixel's lens samples early, where the
    /// rule is measured: at `confidence` 0.9 (the default) without a minimum count
    /// (src/render/camera.rs, [`crate::render::camera::LensRule`]); `None` elsewhere.
    pub blur_variance: Option<f64>,
    pub projection: Projection,
    /// The projection's horizontal and vertical angles in degrees (defaults resolved).
    pub angles: (f64, f64),
    /// `normal { }`: tilts every primary ray's direction (src/render/camera.rs).
    pub normal: Option<Normal>,
    /// `mesh_camera { }` (with `Projection::Mesh`): rays from the faces of meshes
    /// (src/render/mesh_camera.rs).
    pub mesh: Option<MeshView>,
}

/// A mesh camera as the scene wrote it, with `location` and `direction` read the way POV-Ray
/// reads them for this camera: only their z components count.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshView {
    pub rig: Arc<MeshCamera>,
    /// `location`'s z: how far along each face's normal the ray starts.
    pub offset: f64,
    /// `direction` with a negative z: the rays go against the faces' normals.
    pub reverse: bool,
}

/// `mesh_camera { rays distribution [max_distance] mesh { } ... [smooth] }`.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshCamera {
    pub rays_per_pixel: u32,
    pub distribution: MeshDistribution,
    /// Camera rays end here: beyond it they see the background (measured).
    pub max_distance: Option<f64>,
    /// In world space, in the order written.
    pub meshes: Vec<CameraMesh>,
    /// Interpolate the corner normals of smooth faces.
    pub smooth: bool,
}

/// How pixels find their faces (POV-Ray's distribution types 0 to 3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshDistribution {
    /// 0: ray r of a pixel from face `pixel` of mesh r; the pixel averages the rays shot.
    PerMesh,
    /// 1: the meshes' faces in one list, face `pixel` of it.
    Summed,
    /// 2: the image split into side-by-side columns, one per mesh.
    SideBySide,
    /// 3: the pixel's (u, v) found in the faces' uv triangles (texture baking).
    UvMapped,
}

impl MeshDistribution {
    pub fn from_number(n: f64) -> Option<MeshDistribution> {
        Some(match n {
            0.0 => MeshDistribution::PerMesh,
            1.0 => MeshDistribution::Summed,
            2.0 => MeshDistribution::SideBySide,
            3.0 => MeshDistribution::UvMapped,
            _ => return None,
        })
    }
}

/// One camera mesh's triangles, in world space.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CameraMesh {
    pub faces: Vec<CameraFace>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraFace {
    pub corners: [DVec3; 3],
    /// Corner normals of a smooth face.
    pub normals: Option<[DVec3; 3]>,
    pub uvs: Option<[DVec2; 3]>,
}

impl CameraFace {
    /// The face's own normal, (c - a) x (b - a) for corners a, b, c: the direction its rays
    /// go with the default `direction` (measured with POV-Ray 3.7).
    pub fn flat_normal(&self) -> DVec3 {
        let [a, b, c] = self.corners;
        (c - a).cross(b - a).normalize_or(DVec3::Z)
    }

    /// The point and normal at barycentric weights (wa, wb, wc).
    pub fn at(&self, w: [f64; 3], smooth: bool) -> (DVec3, DVec3) {
        let [a, b, c] = self.corners;
        let p = a * w[0] + b * w[1] + c * w[2];
        let flat = self.flat_normal();
        let n = match self.normals.filter(|_| smooth) {
            Some([na, nb, nc]) => {
                let n = na * w[0] + nb * w[1] + nc * w[2];
                // Corner normals point to either side; the face's own normal decides.
                let n = n.normalize_or(flat);
                if n.dot(flat) < 0.0 { -n } else { n }
            }
            None => flat,
        };
        (p, n)
    }

    fn transformed(&self, t: &Transform) -> CameraFace {
        CameraFace {
            corners: self.corners.map(|p| t.point(p)),
            normals: self.normals.map(|ns| ns.map(|n| t.normal(n))),
            uvs: self.uvs,
        }
    }
}

/// How screen points become rays (src/render/camera.rs has the formulas, measured with
/// POV-Ray 3.7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Projection {
    #[default]
    Perspective,
    /// Parallel rays along `direction` from points of the `right` x `up` rectangle.
    Orthographic,
    Fisheye,
    UltraWideAngle,
    Panoramic,
    /// `cylinder 1..4`: vertical or horizontal, from a fixed point or a moving one.
    Cylinder(u8),
    Spherical,
    /// A 180-degree dome view whose lower part is cut off (measured; src/render/camera.rs).
    Omnimax,
    /// `mesh_camera`: rays from mesh faces ([`Camera::mesh`]).
    Mesh,
}

impl Projection {
    /// Perspective and orthographic cameras turn `angle` into the direction's length; the
    /// others read it as their own angle and leave the vectors as written (measured:
    /// panoramic ignores `angle` and uses the lengths of direction and right).
    fn angle_sets_direction(self) -> bool {
        matches!(self, Projection::Perspective | Projection::Orthographic)
    }

    /// The angles when the camera gives none (measured: 90 for fisheye, ultra_wide_angle
    /// and the cylinders; 360 x 180 for spherical, whose vertical angle is otherwise half
    /// the horizontal one).
    fn angles(self, angle: Option<f64>, vertical: Option<f64>) -> (f64, f64) {
        match self {
            Projection::Spherical => {
                let h = angle.unwrap_or(360.0);
                (h, vertical.unwrap_or(h / 2.0))
            }
            _ => {
                let h = angle.unwrap_or(90.0);
                (h, h)
            }
        }
    }
}

impl Default for Camera {
    fn default() -> Self {
        CameraSpec::default().resolve()
    }
}

/// The camera items as a scene writes them. POV-Ray (3.5 and later) lets `look_at` and
/// `angle` appear in any order among the vectors, so they are collected here and combined
/// once in [`CameraSpec::resolve`]; transforms apply afterwards, in the order written.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraSpec {
    pub location: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    pub sky: DVec3,
    pub look_at: Option<DVec3>,
    /// Horizontal field of view in degrees.
    pub angle: Option<f64>,
    pub aperture: f64,
    pub focal_point: DVec3,
    /// POV-Ray's rays per pixel for blur: where its stopping rule is measured a penumbra
    /// sample traces them as POV-Ray does, elsewhere its lens points are the pixel's samples.
    pub blur_samples: u32,
    /// `variance` (POV-Ray 3.7 stops as if it were 1e-4 when none is given, not the 1/128
    /// its documentation names: measured, src/render/camera.rs), `confidence` (the rule is
    /// followed only at 0.9, as written or by default), and whether `blur_samples` gave a
    /// minimum count.
    pub blur_variance: f64,
    pub blur_confidence: f64,
    pub blur_minimum: bool,
    pub projection: Projection,
    /// Spherical's vertical angle (`angle h, v`).
    pub vertical_angle: Option<f64>,
    /// Whether the camera block wrote `up` or `right`: without them (or with `angle`) an
    /// orthographic camera takes its size from the distance to `look_at`.
    pub up_or_right_given: bool,
    pub transform: Transform,
    pub normal: Option<Normal>,
    pub mesh: Option<Arc<MeshCamera>>,
}

impl Default for CameraSpec {
    fn default() -> Self {
        CameraSpec {
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            sky: DVec3::Y,
            look_at: None,
            angle: None,
            aperture: 0.0,
            focal_point: DVec3::ZERO,
            blur_samples: 0,
            blur_variance: 1e-4,
            blur_confidence: 0.9,
            blur_minimum: false,
            projection: Projection::Perspective,
            vertical_angle: None,
            up_or_right_given: false,
            transform: Transform::IDENTITY,
            normal: None,
            mesh: None,
        }
    }
}

impl CameraSpec {
    pub fn resolve(&self) -> Camera {
        let mut direction = self.direction;
        let mut right = self.right;
        let mut up = self.up;
        let angle = self
            .angle
            .filter(|_| self.projection.angle_sets_direction());
        if let Some(angle) = angle {
            let half = (angle.to_radians() * 0.5).tan();
            if half > 0.0 && half.is_finite() {
                direction = direction.normalize_or(DVec3::Z) * (0.5 * right.length() / half);
            }
        }
        if let Some(look_at) = self.look_at {
            // Keep the lengths and the handedness the scene gave, change only the orientation.
            let handedness = up.cross(direction).dot(right);
            let (dl, ul, rl) = (direction.length(), up.length(), right.length());
            let d = (look_at - self.location).normalize_or(DVec3::Z);
            let mut r = self.sky.cross(d);
            if r.length_squared() < 1e-20 {
                // Looking straight along the sky vector: keep the old right vector's direction.
                r = right;
            }
            let r = r.normalize_or(DVec3::X);
            let u = d.cross(r);
            direction = d * dl;
            // A degenerate triple (`up z` with the default direction z) counts as
            // right-handed, as measured with povray: objects/prism3a.pov's camera and an
            // orthographic `up z` view from above both come out mirrored.
            right = r * if handedness <= 0.0 { -rl } else { rl };
            up = u * ul;
        }
        if self.projection == Projection::Orthographic
            && (self.angle.is_some() || !self.up_or_right_given)
        {
            // POV-Ray's documented second orthographic mode: the same image area as the
            // perspective camera would show at the look_at distance. Measured with POV-Ray
            // 3.7: the width is |right| * distance / |direction| (2 distance tan(angle / 2)
            // with `angle`), up scales alike, and without `look_at` the distance is to
            // POV-Ray's default look_at <0, 0, 1>.
            let look_at = self.look_at.unwrap_or(DVec3::Z);
            let dl = direction.length();
            let scale = (look_at - self.location).length() / dl;
            if dl > 0.0 && scale > 0.0 && scale.is_finite() {
                right *= scale;
                up *= scale;
            }
        }
        let t = &self.transform;
        let mesh = self.mesh.as_ref().map(|rig| MeshView {
            rig: if t.is_identity() {
                rig.clone()
            } else {
                Arc::new(MeshCamera {
                    meshes: rig
                        .meshes
                        .iter()
                        .map(|m| CameraMesh {
                            faces: m.faces.iter().map(|f| f.transformed(t)).collect(),
                        })
                        .collect(),
                    ..(**rig).clone()
                })
            },
            offset: self.location.z,
            reverse: self.direction.z < 0.0,
        });
        Camera {
            location: t.point(self.location),
            direction: t.vector(direction),
            right: t.vector(right),
            up: t.vector(up),
            // POV-Ray blurs only with `blur_samples` (measured: `aperture 2` alone renders
            // as sharp as a pinhole).
            aperture: if self.blur_samples > 0 {
                self.aperture
            } else {
                0.0
            },
            focal_point: t.point(self.focal_point),
            blur_samples: self.blur_samples,
            blur_variance: (self.blur_confidence == 0.9 && !self.blur_minimum)
                .then_some(self.blur_variance),
            projection: self.projection,
            angles: self.projection.angles(self.angle, self.vertical_angle),
            normal: self.normal.clone(),
            mesh,
        }
    }
}
