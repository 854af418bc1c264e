//! Primary rays: screen point (x, y) in [-1/2, 1/2]^2, y up, to a ray. The projections
//! other than perspective and orthographic were measured with POV-Ray 3.7: a camera at the
//! centre of an emitting sphere whose colour is the direction's x, y or z component, one
//! ray per pixel centre (40 x 30), the direction read back from the image. With D, R, U
//! the camera's direction, right and up, a hat for a unit vector, and the angles of
//! `Camera::angles` in radians:
//! - cylinder 1 (vertical, fixed point): a = x h; D^ cos a + R^ sin a + y U.
//! - cylinder 2 (horizontal, fixed point): b = y h; D^ cos b + U^ sin b + x R.
//! - cylinder 3 and 4: as 1 and 2, the origin moved by y U (3) or x R (4), the direction
//!   without that term.
//! - spherical: longitude x h, latitude y v; cos(lat) (D^ cos lon + R^ sin lon) + U^ sin lat.
//! - fisheye: (x0, y0) = (2 x |R| / |U|, 2 y), r = |(x0, y0)|; no ray outside r = 1 (the
//!   pixel is black, not the background); theta = r h / 2 from D^ toward
//!   (R^ x0 + U^ y0) / r.
//! - ultra_wide_angle: a = x h, b = y h |U| / |R|; R^ sin a + U^ sin b + D^ cos a cos b.
//! - panoramic: the angle is ignored; a = pi x, b = pi y; D cos a + R sin a + U^ tan b,
//!   with D and R at their own lengths.
//! - omnimax: the angle is ignored. With A = |R| / |U|, (X, Y) = (2 x, 2 y / A) when
//!   A <= 1, and (2 x s A, 2 y s + 1 - s) with s = 0.7791 when A > 1 (the image then spans
//!   the visible part from the top of the dome to the cut below); r = |(X, Y)|, no ray for
//!   r > 1; theta = 1.41127 r - 0.09443 r^3 + 0.25678 r^5 (radians) from D^ toward
//!   (R^ X + U^ Y) / r; no ray below the plane through the camera where U^ and D^ parts are
//!   opposite and equal (more than 45 degrees down). Fitted to 400 x 400 measured
//!   directions: residual 2.6e-4 rad RMS, the half-float output's own precision.
//!
//! Camera `normal { }` tilts the unit ray direction as a surface normal is tilted, with the
//! pattern read at the screen point (x, y, 0) and the tilt in world axes. Measured with
//! `normal { function { x*x } 1 }`: the tilt follows x alone (not x |R|, not the direction,
//! not the location), and neither `look_at` nor the camera's transforms turn it (fit to
//! 1e-3 RMS, the tetrahedral difference's own offset on a quadratic included).

use glam::DVec3;

use super::sampler::concentric_disc;
use crate::appearance::normal::perturb;
use crate::geometry::Ray;
use crate::scene::{Camera, Projection};

/// The primary ray through screen point (x, y), leaving the lens at `lens` in [0, 1)^2
/// (ignored for a pinhole camera); `None` where the projection has no ray (outside a
/// fisheye's circle). With focal blur, every ray through the same screen point meets the
/// others on the plane through the focal point, perpendicular to the viewing direction.
pub fn camera_ray(camera: &Camera, x: f64, y: f64, lens: (f64, f64)) -> Option<Ray> {
    let ray = pinhole_or_lens_ray(camera, x, y, lens)?;
    Some(match &camera.normal {
        Some(normal) => Ray::new(
            ray.origin,
            perturb(normal, DVec3::new(x, y, 0.0), ray.direction),
        ),
        None => ray,
    })
}

fn pinhole_or_lens_ray(camera: &Camera, x: f64, y: f64, lens: (f64, f64)) -> Option<Ray> {
    let (origin, dir) = match camera.projection {
        Projection::Orthographic => {
            let origin = camera.location + camera.right * x + camera.up * y;
            return Some(Ray::new(origin, unit(camera.direction, DVec3::Z)));
        }
        Projection::Perspective => (
            camera.location,
            camera.direction + camera.right * x + camera.up * y,
        ),
        other => wide(camera, other, x, y)?,
    };
    if camera.aperture <= 0.0 {
        return Some(Ray::new(origin, unit(dir, DVec3::Z)));
    }
    Some(blurred(camera, origin, dir, lens))
}

fn unit(v: DVec3, fallback: DVec3) -> DVec3 {
    v.normalize_or(fallback)
}

/// The origin and direction of the projections that bend rays (module documentation).
fn wide(camera: &Camera, projection: Projection, x: f64, y: f64) -> Option<(DVec3, DVec3)> {
    let (d, r, u) = (camera.direction, camera.right, camera.up);
    let (dh, rh, uh) = (unit(d, DVec3::Z), unit(r, DVec3::X), unit(u, DVec3::Y));
    let (h, v) = (camera.angles.0.to_radians(), camera.angles.1.to_radians());
    let at = camera.location;
    Some(match projection {
        Projection::Cylinder(kind) => {
            let vertical = kind == 1 || kind == 3;
            let moving = kind >= 3;
            let (a, across, along, shift) = if vertical {
                (x * h, rh, u * y, u * y)
            } else {
                (y * h, uh, r * x, r * x)
            };
            let turned = dh * a.cos() + across * a.sin();
            if moving {
                (at + shift, turned)
            } else {
                (at, turned + along)
            }
        }
        Projection::Spherical => {
            let (lon, lat) = (x * h, y * v);
            (
                at,
                (dh * lon.cos() + rh * lon.sin()) * lat.cos() + uh * lat.sin(),
            )
        }
        Projection::Fisheye => {
            let aspect = r.length() / u.length();
            let (x0, y0) = (2.0 * x * aspect, 2.0 * y);
            let radius = x0.hypot(y0);
            if radius > 1.0 {
                return None;
            }
            let theta = radius * h / 2.0;
            let side = if radius > 0.0 {
                (rh * x0 + uh * y0) / radius
            } else {
                DVec3::ZERO
            };
            (at, dh * theta.cos() + side * theta.sin())
        }
        Projection::UltraWideAngle => {
            let (a, b) = (x * h, y * h * u.length() / r.length());
            (at, rh * a.sin() + uh * b.sin() + dh * (a.cos() * b.cos()))
        }
        Projection::Panoramic => {
            let (a, b) = (std::f64::consts::PI * x, std::f64::consts::PI * y);
            (at, d * a.cos() + r * a.sin() + uh * b.tan())
        }
        Projection::Omnimax => (at, omnimax(dh, rh, uh, r.length() / u.length(), x, y)?),
        Projection::Perspective | Projection::Orthographic => (at, d + r * x + u * y),
        // Mesh cameras shoot from their faces (src/render/mesh_camera.rs), not the screen.
        Projection::Mesh => return None,
    })
}

/// The omnimax direction (module documentation for the measured formula).
fn omnimax(dh: DVec3, rh: DVec3, uh: DVec3, aspect: f64, x: f64, y: f64) -> Option<DVec3> {
    /// The vertical scale that fits the dome's visible height into a wide image.
    const WIDE_SCALE: f64 = 0.7791;
    let (sx, sy) = if aspect > 1.0 {
        (
            2.0 * x * WIDE_SCALE * aspect,
            2.0 * y * WIDE_SCALE + 1.0 - WIDE_SCALE,
        )
    } else {
        (2.0 * x, 2.0 * y / aspect)
    };
    let radius = sx.hypot(sy);
    if radius > 1.0 {
        return None;
    }
    let r2 = radius * radius;
    let theta = radius * (1.41127 + r2 * (-0.09443 + r2 * 0.25678));
    let side = if radius > 0.0 {
        (rh * sx + uh * sy) / radius
    } else {
        DVec3::ZERO
    };
    let (sin, cos) = theta.sin_cos();
    let dir = dh * cos + side * sin;
    // The dome's lower edge: nothing more than 45 degrees below the viewing direction.
    if side.dot(uh) * sin < -cos {
        return None;
    }
    Some(dir)
}

/// POV-Ray 3.7's lens for 7, 19 and 37 `blur_samples`, measured from the blur of a small
/// bright sphere far out of focus (its image is the lens's shape, point-mirrored): a
/// hexagonal grid of 7, 19 or 37 rectangular cells (1, 2 or 3 rings), in rows along
/// `right` of 2k + 1 - |r| cells for r in -k..=k, each cell jittered whole, so that the
/// lens is uniform over a stepped hexagon. A cell is HEX_CELL x aperture / (k + 1) wide
/// (measured 0.561, 0.571 and 0.575 at aperture 2 for k = 1, 2, 3) and sqrt(3)/2 of that
/// high (measured 0.90, 0.90, 0.88). scenes/focal_blur.pov with those counts converges to
/// POV-Ray's image (160x120, 1024 spp: sqrt(B) 0.0000, 0.00025, 0.00068). 16 samples are
/// measured ([`LENS_16`]); other counts up to 37 take the next grid: POV-Ray's lens for them
/// is the grid below plus jittered squares placed unevenly, a different shape for each
/// count, which the grid only approximates.
const HEX_CELL: f64 = 0.2875;
/// Beyond 37 samples POV-Ray's lens is another (at 64 and more a disc of clumps, from
/// samples placed at random): the uniform disc fitted by RMSE against POV-Ray renders
/// (camera/focalblur.pov, 120 samples, passes with sqrt(B) = 0.0010).
const DISC_RADIUS: f64 = 0.25;

/// The rings of the hexagonal lens grid for `blur_samples` ([`HEX_CELL`]: exact at 7, 19
/// and 37, the nearest shape measured between); `None` beyond 37.
fn hex_rings(blur_samples: u32) -> Option<i32> {
    match blur_samples {
        0..=7 => Some(1),
        8..=19 => Some(2),
        20..=37 => Some(3),
        _ => None,
    }
}

/// POV-Ray 3.7's lens for 16 `blur_samples`, measured as the hexagonal grids were, with
/// `variance 0` so that every sample is taken (four 4000x4000 renders of a small sphere far
/// out of focus fitted together by least squares, scripts/lens_fit.py; the same with a 4:3
/// camera, and at the aperture, angle and focus of scenes/focal_blur.pov): 16 squares, one a
/// sample, each jittered whole, [`LENS_16_SIDE`] x aperture a side (fitted 0.1248-0.1253),
/// centred on the one-ring hexagonal grid's 7 points (spacing 0.1445 x aperture along right,
/// rows 0.1256 apart: [`HEX_CELL`]'s grid) and on 9 points placed unevenly, here in aperture
/// units and in the order POV-Ray traces them (the grid first; then the three groups its
/// stopping rule tests after, [`LensRule`]). Sampled so, scenes/focal_blur.pov with `variance 0`
/// converges to POV-Ray's image (160x120, 4 x 256 spp: sqrt(B) 0.0000).
const LENS_16: [(f64, f64); 16] = [
    (0.0, 0.0),
    (-0.1445, 0.0),
    (0.1445, 0.0),
    (-0.07226, 0.12557),
    (0.07226, 0.12557),
    (-0.07226, -0.12557),
    (0.07226, -0.12557),
    (-0.08321, -0.02943),
    (0.03419, 0.19519),
    (0.16608, -0.13915),
    (0.02692, -0.15074),
    (-0.09618, -0.10141),
    (0.04745, 0.04048),
    (0.18195, -0.04291),
    (-0.22015, 0.08003),
    (-0.06509, 0.21597),
];
const LENS_16_SIDE: f64 = 0.125;

/// POV-Ray's adaptive stop for a pixel's lens samples under its default `confidence` and
/// `variance`, measured for 16, 19 and 37 `blur_samples` (7 never stops early): it traces
/// the lens's cells in an order of its own and, after certain counts (16: the 7th, 11th,
/// 15th; 19: 7th, 13th; 37: 7th, 13th, 19th, then every 4th to the 35th; none between),
/// stops if in every colour channel the samples' variance (sum of squared deviations over
/// n - 1) is below that count's threshold. Measured with a dim sphere seen through one
/// cell (a pixel's value is its hits over the samples it took, so it tells where it
/// stopped): one hit of brightness c stops at n where c^2 / n is below the threshold, found
/// by bisection to 1e-4 of c; two hits among 7 stop below c = 0.034 (the variance's 0.0339,
/// where a test of the samples' range would give 0.0437); a grey background of 0.3 or 0.6
/// moves nothing; red, green or grey alone stop at the same c. The thresholds depend on the
/// count as well as on n (at n = 7: 16 samples 2.72e-4, 19 2.16e-4, 37 9.17e-5). The order
/// was read from which cells pixels that stopped at each count saw (a background graded
/// across the lens set where they stopped, a bright small sphere showed the cells sampled):
/// the grid's coarsest hexagon first, then rings inward and outward. The thresholds scale
/// with `variance` ([`DEFAULT_VARIANCE`]); `confidence` changes them otherwise (16 samples,
/// variance 1e-4: one hit stops at 7 below c = 0.0505, 0.0437, 0.0394 for 0.5, 0.9, 0.975,
/// at 11 below 0.0982, 0.0933, 0.0901: not one factor), so only the default 0.9 is
/// followed; under another, or a minimum count, penumbra takes every sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LensRule {
    /// The lens's cells ([`lens_offset`]'s numbering) in the order POV-Ray traces them.
    pub order: &'static [u8],
    /// After how many samples the rule is tested, and the variance below which it stops
    /// under the default `variance`.
    pub checks: &'static [(u32, f64)],
    /// The written `variance` over the default: the thresholds scale with it.
    pub scale: f64,
}

impl LensRule {
    /// The `lens` value of [`camera_ray`] for POV-Ray's sample `j`, jittered by `(a, b)`.
    pub fn lens(&self, j: usize, (a, b): (f64, f64)) -> (f64, f64) {
        let cells = self.order.len() as f64;
        ((f64::from(self.order[j]) + a) / cells, b)
    }
}

/// [`LENS_16`] is in POV-Ray's order already.
const ORDER_16: [u8; 16] = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15];
const CHECKS_16: [(u32, f64); 3] = [(7, 2.72413e-4), (11, 7.91294e-4), (15, 1.60572e-3)];
/// The 19-cell grid: its coarse hexagon (centre, two along right, four on the outer rows),
/// the outer ring's other six, then the inner ring.
const ORDER_19: [u8; 19] = [
    9, 7, 11, 0, 2, 16, 18, 1, 3, 6, 12, 15, 17, 4, 5, 8, 10, 13, 14,
];
const CHECKS_19: [(u32, f64); 2] = [(7, 2.16460e-4), (13, 9.20880e-4)];
/// The 37-cell grid in groups of 7, 6, 6, 4, 4, 4, 4 and 2 (the last pair on the vertical
/// axis next to the centre).
const ORDER_37: [u8; 37] = [
    18, 15, 21, 0, 3, 33, 36, 5, 7, 16, 20, 29, 31, 11, 12, 17, 19, 24, 25, 9, 14, 22, 27, 4, 8,
    28, 32, 1, 2, 34, 35, 10, 13, 23, 26, 6, 30,
];
const CHECKS_37: [(u32, f64); 7] = [
    (7, 9.16733e-5),
    (13, 3.90879e-4),
    (19, 9.18981e-4),
    (23, 1.40305e-3),
    (27, 1.94514e-3),
    (31, 2.66579e-3),
    (35, 3.48264e-3),
];

/// POV-Ray's `variance` when none is written: its thresholds are those of `variance 1e-4`
/// written out (16 samples: one hit stops at 7 below c = 0.043662-0.043672 either way), not
/// of the 1/128 its documentation gives. Written values scale the thresholds in proportion:
/// one hit stops at 7 below c^2 = 19.10 x variance at 1/128, 1/1024 and 1/8192 (0.3863,
/// 0.1372, 0.0485).
const DEFAULT_VARIANCE: f64 = 1e-4;

/// The stopping rule of the camera's focal blur where it is measured (see [`LensRule`]).
pub fn lens_rule(camera: &Camera) -> Option<LensRule> {
    let variance = camera.blur_variance?;
    if camera.aperture <= 0.0 || camera.mesh.is_some() {
        return None;
    }
    let (order, checks): (&'static [u8], &'static [(u32, f64)]) = match camera.blur_samples {
        16 => (&ORDER_16, &CHECKS_16),
        19 => (&ORDER_19, &CHECKS_19),
        37 => (&ORDER_37, &CHECKS_37),
        _ => return None,
    };
    Some(LensRule {
        order,
        checks,
        scale: variance / DEFAULT_VARIANCE,
    })
}

/// The lens point, along the unit right and up vectors, of a uniform `lens` sample in
/// [0, 1)^2: the first coordinate picks the cell (its fraction places the point across
/// it), the second places it up the cell, so that a stratified pair stays stratified.
fn lens_offset(camera: &Camera, lens: (f64, f64)) -> (f64, f64) {
    if camera.blur_samples == 16 {
        let scaled = lens.0 * 16.0;
        let cell = (scaled as usize).min(15);
        let (x, y) = LENS_16[cell];
        let across = scaled - cell as f64 - 0.5;
        let a = camera.aperture;
        return (
            (x + across * LENS_16_SIDE) * a,
            (y + (lens.1 - 0.5) * LENS_16_SIDE) * a,
        );
    }
    let Some(k) = hex_rings(camera.blur_samples) else {
        let (dx, dy) = concentric_disc(lens.0, lens.1);
        let radius = DISC_RADIUS * camera.aperture;
        return (dx * radius, dy * radius);
    };
    let w = HEX_CELL * camera.aperture / f64::from(k + 1);
    let h = w * 0.75f64.sqrt();
    let cells = 3 * k * (k + 1) + 1;
    let scaled = lens.0 * f64::from(cells);
    let mut cell = (scaled as i32).min(cells - 1);
    let across = scaled - f64::from(cell);
    for row in -k..=k {
        let n = 2 * k + 1 - row.abs();
        if cell < n {
            let x = f64::from(cell) - f64::from(n) * 0.5 + across;
            return (x * w, (f64::from(row) + lens.1 - 0.5) * h);
        }
        cell -= n;
    }
    // Not reached: the cell index is below the grid's count.
    (0.0, 0.0)
}

/// Focal blur: the ray from a point of the lens through where the pinhole ray meets the
/// focal plane.
fn blurred(camera: &Camera, origin: DVec3, dir: DVec3, lens: (f64, f64)) -> Ray {
    let forward = unit(camera.direction, DVec3::Z);
    let focus_distance = (camera.focal_point - origin).dot(forward);
    let along = dir.dot(forward);
    if focus_distance <= 0.0 || along <= 0.0 {
        return Ray::new(origin, unit(dir, DVec3::Z));
    }
    let focus = origin + dir * (focus_distance / along);
    let (dx, dy) = lens_offset(camera, lens);
    let lens_point = origin + unit(camera.right, DVec3::X) * dx + unit(camera.up, DVec3::Y) * dy;
    Ray::new(lens_point, unit(focus - lens_point, DVec3::Z))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::CameraSpec;

    fn camera(projection: Projection, angle: Option<f64>) -> Camera {
        CameraSpec {
            projection,
            angle,
            look_at: Some(DVec3::Z),
            ..CameraSpec::default()
        }
        .resolve()
    }

    #[test]
    fn the_screen_centre_looks_along_the_direction() {
        for p in [
            Projection::Fisheye,
            Projection::UltraWideAngle,
            Projection::Panoramic,
            Projection::Spherical,
            Projection::Cylinder(1),
            Projection::Cylinder(2),
        ] {
            let ray = camera_ray(&camera(p, None), 0.0, 0.0, (0.5, 0.5)).expect("a ray");
            assert!((ray.direction - DVec3::Z).length() < 1e-12, "{p:?}");
        }
    }

    #[test]
    fn edges_reach_the_angles() {
        // The right edge of a 180-degree fisheye's circle looks sideways; a spherical
        // camera's corner at 360 x 180 looks straight up; a cylinder 1 at 120 degrees turns
        // 60 degrees at the right edge.
        let fisheye = camera(Projection::Fisheye, Some(180.0));
        let x = 0.5 / (fisheye.right.length() / fisheye.up.length());
        let side = camera_ray(&fisheye, x, 0.0, (0.5, 0.5)).expect("on the circle");
        assert!(
            (side.direction - DVec3::X).length() < 1e-9,
            "{:?}",
            side.direction
        );
        assert!(camera_ray(&fisheye, 0.5, 0.5, (0.5, 0.5)).is_none());
        let up = camera_ray(&camera(Projection::Spherical, None), 0.2, 0.5, (0.5, 0.5));
        assert!((up.expect("a ray").direction - DVec3::Y).length() < 1e-9);
        let cyl = camera_ray(
            &camera(Projection::Cylinder(1), Some(120.0)),
            0.5,
            0.0,
            (0.5, 0.5),
        );
        let d = cyl.expect("a ray").direction;
        assert!((d.x.atan2(d.z).to_degrees() - 60.0).abs() < 1e-9);
    }

    #[test]
    fn moving_cylinders_move_the_origin_not_the_direction() {
        let c = camera(Projection::Cylinder(3), None);
        let ray = camera_ray(&c, 0.0, 0.4, (0.5, 0.5)).expect("a ray");
        assert!((ray.origin - c.up * 0.4).length() < 1e-12);
        assert!((ray.direction - DVec3::Z).length() < 1e-12);
    }

    #[test]
    fn omnimax_matches_povray_measurements() {
        // Measured with POV-Ray 3.7 (81 x 61, right 1.33 x): the image centre looks 17.8
        // degrees up, the top centre nearly straight up, the bottom row at the 45-degree cut;
        // a square camera looks straight ahead at its centre.
        let wide = camera(Projection::Omnimax, None);
        let d = camera_ray(&wide, 0.0, 0.0, (0.5, 0.5))
            .expect("a ray")
            .direction;
        assert!((d.y.asin().to_degrees() - 17.8).abs() < 0.1, "{d:?}");
        let top = camera_ray(&wide, 0.0, 0.4918, (0.5, 0.5))
            .expect("a ray")
            .direction;
        assert!(
            (top.y.atan2(top.z).to_degrees() - 88.43).abs() < 0.2,
            "{top:?}"
        );
        let side = camera_ray(&wide, 0.4444, 0.0, (0.5, 0.5))
            .expect("a ray")
            .direction;
        assert!(
            (side - DVec3::new(0.9656, 0.2314, 0.1182)).length() < 2e-3,
            "{side:?}"
        );
        assert!(camera_ray(&wide, 0.4938, 0.0, (0.5, 0.5)).is_none());
        let square = CameraSpec {
            projection: Projection::Omnimax,
            right: DVec3::X,
            look_at: Some(DVec3::Z),
            ..CameraSpec::default()
        }
        .resolve();
        let d = camera_ray(&square, 0.0, 0.0, (0.5, 0.5))
            .expect("a ray")
            .direction;
        assert!((d - DVec3::Z).length() < 1e-12);
        assert!(
            camera_ray(&square, 0.0, -0.3, (0.5, 0.5)).is_none(),
            "below the cut"
        );
        assert!(camera_ray(&square, 0.0, -0.27, (0.5, 0.5)).is_some());
    }

    fn blur_camera(blur_samples: u32) -> Camera {
        CameraSpec {
            aperture: 2.0,
            blur_samples,
            focal_point: DVec3::new(0.0, 0.0, 20.0),
            look_at: Some(DVec3::Z),
            ..CameraSpec::default()
        }
        .resolve()
    }

    /// The lens for up to 37 samples (POV-Ray's own at 7, 19 and 37): an equal share in
    /// each cell of its grid (rows of 2k + 1 - |r| cells along right, sqrt(3)/2 as high as
    /// wide), nothing outside them.
    #[test]
    fn the_lens_fills_its_hexagonal_grid_evenly() {
        for (samples, k) in [(1, 1), (7, 1), (18, 2), (19, 2), (20, 3), (37, 3)] {
            let camera = blur_camera(samples);
            let w = HEX_CELL * 2.0 / f64::from(k + 1);
            let h = w * 0.75f64.sqrt();
            let cells = (3 * k * (k + 1) + 1) as usize;
            let mut count = std::collections::HashMap::new();
            let n = 96 * cells;
            for i in 0..n {
                for j in 0..8 {
                    let lens = ((i as f64 + 0.5) / n as f64, (j as f64 + 0.5) / 8.0);
                    let (x, y) = lens_offset(&camera, lens);
                    let row = (y / h).round() as i32;
                    assert!(row.abs() <= k, "{samples}: y {y} outside the rows");
                    let across = f64::from(2 * k + 1 - row.abs()) * 0.5 * w;
                    assert!(x.abs() < across, "{samples}: x {x} outside row {row}");
                    assert!((y - f64::from(row) * h).abs() < 0.5 * h);
                    *count.entry((row, ((x + across) / w) as i32)).or_insert(0) += 1;
                }
            }
            assert_eq!(count.len(), cells, "{samples} samples");
            assert!(count.values().all(|&c| c == 96 * 8), "{samples}: {count:?}");
        }
        // Beyond 37 samples, the disc.
        let (x, y) = lens_offset(&blur_camera(38), (0.999, 0.5));
        assert!(((x * x + y * y).sqrt() - DISC_RADIUS * 2.0).abs() < 0.01);
    }

    /// The lens for 16 samples: an equal share of a uniform sample in each of its 16
    /// squares, in their order, uniform within each.
    #[test]
    fn the_lens_of_sixteen_fills_its_squares_evenly() {
        let camera = blur_camera(16);
        let side = LENS_16_SIDE * camera.aperture;
        for (cell, &(cx, cy)) in LENS_16.iter().enumerate() {
            for (i, j) in [(0, 0), (7, 3), (15, 15)] {
                let across = (f64::from(i) + 0.5) / 16.0;
                let up = (f64::from(j) + 0.5) / 16.0;
                let lens = ((cell as f64 + across) / 16.0, up);
                let (x, y) = lens_offset(&camera, lens);
                let expected = (
                    cx * camera.aperture + (across - 0.5) * side,
                    cy * camera.aperture + (up - 0.5) * side,
                );
                assert!((x - expected.0).abs() < 1e-12 && (y - expected.1).abs() < 1e-12);
            }
        }
        // The one-ring grid's seven come first (a pixel's first test sees only them): the
        // centre, two along right at the spacing, four half a spacing out on the rows.
        let (w, h) = (0.1445, 0.12557);
        let grid = [(0.0, 0.0), (-w, 0.0), (w, 0.0)].into_iter().chain(
            [h, -h]
                .into_iter()
                .flat_map(|y| [(-w / 2.0, y), (w / 2.0, y)]),
        );
        for (a, b) in grid.zip(&LENS_16[..7]) {
            assert!(
                (a.0 - b.0).abs() < 1e-4 && (a.1 - b.1).abs() < 1e-4,
                "{a:?} {b:?}"
            );
        }
    }

    /// POV-Ray blurs only when `blur_samples` is given.
    #[test]
    fn an_aperture_without_blur_samples_is_a_pinhole() {
        assert_eq!(blur_camera(0).aperture, 0.0);
        assert_eq!(blur_camera(1).aperture, 2.0);
    }
}
