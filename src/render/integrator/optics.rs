//! The geometric optics of a surface: Fresnel reflectance, refraction, mirror directions,
//! interior fade. Pure functions, each checked against a closed form.

use glam::DVec3;

use crate::render::prepared::Material;

/// Unpolarised Fresnel reflectance with relative index n and cos c of the incidence angle;
/// 1 under total internal reflection.
pub fn fresnel(c: f64, n: f64) -> f64 {
    let g2 = n * n + c * c - 1.0;
    if g2 <= 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c);
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
}

/// Heckbert's refraction: `eta = n_from / n_to`, `n` facing the incoming direction `d`;
/// `None` under total internal reflection.
pub fn refract(d: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    let c = -d.dot(n);
    let t = 1.0 + eta * eta * (c * c - 1.0);
    if t < 0.0 {
        return None;
    }
    Some((eta * d + (eta * c - t.sqrt()) * n).normalize())
}

/// The mirror direction of `d` in the shading normal `n` (facing the ray), kept outside the
/// true surface whose normal facing the ray is `outside`. A perturbed normal can send the
/// mirror ray into the surface. POV-Ray then mirrors it again in the true surface (measured:
/// the component along the geometric normal changes sign, the others keep theirs), unless
/// the ray also lies behind the perturbed normal (the normal was tilted past the ray): then
/// it reflects `d` in the true surface alone (measured: exactly the unperturbed direction).
pub(super) fn mirror_direction(d: DVec3, n: DVec3, outside: DVec3) -> DVec3 {
    let mirror = d - 2.0 * d.dot(n) * n;
    let below = mirror.dot(outside);
    if below >= 0.0 {
        mirror
    } else if mirror.dot(n) < 0.0 {
        d - 2.0 * d.dot(outside) * outside
    } else {
        mirror - 2.0 * below * outside
    }
}

/// POV-Ray's fake caustics: what `interior { caustics power }` multiplies the light of a
/// shadow ray by where it crosses the object's surface at `cos` (the cosine between the ray
/// and the surface's perturbed normal, either way round): `1 + |cos|^(45 power)`, at each
/// surface crossed. Measured with a parallel light straight above a transparent tilted
/// plane (ior 1, rgbf 1) over a white floor: the floor doubles where the plane is level,
/// whatever the power, and at power 0.02 it is 1.9863, 1.9453, 1.8789, 1.7871, 1.6719,
/// 1.5361, 1.3809, 1.2070 at 10 .. 80 degrees of tilt, an exponent of 45.0 +- 0.2 times the
/// power at every angle (power 0.01 to 10 and -1 alike: power 1 at 10 degrees 1.5020). It
/// multiplies the filtered light (filter 0.5 transmit 0.25 level: 0.75 x 2), ignores the
/// ior and the side the normal faces, applies at both surfaces of a sphere (the floor under
/// a glass sphere, 1 + c^0.9 squared to 1e-3), and follows the normal's perturbation (bumps
/// on the level plane spread the floor between 1 and 2). A power of 0 is none.
pub(super) fn caustic_factor(power: f64, cos: f64) -> f64 {
    if power == 0.0 {
        return 1.0;
    }
    1.0 + cos.abs().max(1e-12).powf(CAUSTIC_EXPONENT * power)
}

/// The exponent of [`caustic_factor`] per unit of `caustics`.
const CAUSTIC_EXPONENT: f64 = 45.0;

/// Interior fade over `distance` inside an object.
pub(super) fn fade(material: &Material, distance: f64) -> DVec3 {
    let colour = material.interior.fade_colour;
    let ratio = distance / material.interior.fade_distance;
    if material.interior.fade_power >= 1000.0 {
        DVec3::new(
            (-(1.0 - colour.x) * ratio).exp(),
            (-(1.0 - colour.y) * ratio).exp(),
            (-(1.0 - colour.z) * ratio).exp(),
        )
    } else {
        colour + (DVec3::ONE - colour) / (1.0 + ratio.powf(material.interior.fade_power))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mirror_rays_stay_outside_the_true_surface() {
        let d = DVec3::new(0.0, -1.0, 1.0).normalize();
        let up = DVec3::Y;
        // Unperturbed: the plain mirror.
        let m = mirror_direction(d, up, up);
        assert!((m - DVec3::new(0.0, 1.0, 1.0).normalize()).length() < 1e-12);
        // Tilted sideways far enough to send the mirror below: only y changes sign.
        let n = DVec3::new(1.6, 1.0, 0.0).normalize();
        let raw = d - 2.0 * d.dot(n) * n;
        assert!(raw.y < 0.0 && raw.dot(n) > 0.0);
        let m = mirror_direction(d, n, up);
        assert!((m - DVec3::new(raw.x, -raw.y, raw.z)).length() < 1e-12);
        // Tilted past the ray (the ray meets the perturbed normal's back): the true mirror.
        let n = DVec3::new(0.0, 1.0, 2.0).normalize();
        assert!(d.dot(n) > 0.0);
        let m = mirror_direction(d, n, up);
        assert!((m - DVec3::new(0.0, 1.0, 1.0).normalize()).length() < 1e-12);
    }

    #[test]
    fn fresnel_conserves_and_saturates() {
        // Normal incidence into glass: ((n-1)/(n+1))^2 = 0.04 for n = 1.5.
        assert!((fresnel(1.0, 1.5) - 0.04).abs() < 1e-12);
        // Beyond the critical angle from inside glass: total reflection, no NaN.
        let critical = (1.0f64 - (1.0 / 1.5f64).powi(2)).sqrt();
        for c in [critical - 1e-9, critical * 0.5, 0.0] {
            let r = fresnel(c, 1.0 / 1.5);
            assert!(r.is_finite() && (r - 1.0).abs() < 1e-6, "{c}: {r}");
        }
        for c in [0.01, 0.3, 0.7, 0.99] {
            let r = fresnel(c, 1.33);
            assert!((0.0..=1.0).contains(&r));
        }
    }

    #[test]
    fn caustics_follow_the_measured_law() {
        // POV-Ray 3.7: the floor under a level plane doubles; caustics 0.02 at tilts of
        // 10 .. 80 degrees, caustics 1 at 10 and 20 degrees, caustics -1 at 10 degrees.
        assert_eq!(caustic_factor(0.02, 1.0), 2.0);
        let measured = [
            (0.02, 10.0, 1.9863),
            (0.02, 30.0, 1.8789),
            (0.02, 50.0, 1.6719),
            (0.02, 80.0, 1.2070),
            (1.0, 10.0, 1.5020),
            (1.0, 20.0, 1.0605),
            (2.0, 10.0, 1.2520),
            (-1.0, 10.0, 2.9922),
        ];
        for (power, tilt, floor) in measured {
            let cos = f64::to_radians(tilt).cos();
            let f = caustic_factor(power, cos);
            assert!(
                (f - floor).abs() < 2e-3,
                "{power} at {tilt}: {f} against {floor}"
            );
            assert_eq!(f, caustic_factor(power, -cos));
        }
        assert_eq!(caustic_factor(0.0, 1.0), 1.0);
    }

    #[test]
    fn refraction_follows_snell() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        let n = DVec3::Y;
        let t = refract(d, n, 1.0 / 1.5).unwrap();
        // sin_t = sin_i / 1.5
        assert!((t.x - 0.6 / 1.5).abs() < 1e-12);
        assert!(refract(DVec3::new(0.9, -(1.0f64 - 0.81).sqrt(), 0.0), n, 1.5).is_none());
    }
}
