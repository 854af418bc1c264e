//! POV-Ray's finish formulas as pure functions, so each can be checked against
//! hand-computed values. `n` is the normal facing the viewer, `l` the unit vector to the
//! light, `d` the incoming ray direction (unit).

use glam::DVec3;

/// `x^e` for the exponents finishes hold. Most are whole numbers (brilliance 2, phong_size
/// 40, roughness 0.05 is 20): those are a few multiplications, where `powf` took 1.8% of
/// scenes/checker.pov's instructions. They agree with `powf` to a few units in the last
/// place.
fn power(x: f64, e: f64) -> f64 {
    if e.fract() == 0.0 && e.abs() <= 256.0 {
        x.powi(e as i32)
    } else {
        x.powf(e)
    }
}

/// Diffuse: `diffuse * (N.L)^brilliance`, no 1/pi, zero when N.L < 1e-10.
pub fn diffuse_factor(diffuse: f64, brilliance: f64, n_dot_l: f64) -> f64 {
    if n_dot_l < 1e-10 || diffuse == 0.0 {
        return 0.0;
    }
    let c = if brilliance == 1.0 {
        n_dot_l
    } else {
        power(n_dot_l, brilliance)
    };
    diffuse * c
}

/// The diffuse part of one light, as a multiple of pigment times light colour: the diffuse
/// factor scaled by the opacity `att`, less the mean of `crand`'s noise. POV-Ray subtracts
/// `crand * u` (u uniform in [0, 1), the same u for r, g and b, drawn afresh per light) from
/// the diffuse intensity, after the opacity and without clipping, and only where the light
/// adds diffuse light at all; penumbra subtracts its expectation, `crand / 2`, which is the
/// image POV-Ray converges to, without the grain.
pub fn diffuse_term(diffuse: f64, brilliance: f64, n_dot_l: f64, att: f64, crand: f64) -> f64 {
    let d = diffuse_factor(diffuse, brilliance, n_dot_l);
    if d == 0.0 {
        return 0.0;
    }
    d * att - 0.5 * crand
}

/// The thickness variation `irid { turbulence u }` adds: povray's thickness reads
/// t (1 + u Y) with Y of mean 0.97 and standard deviation 0.60 over a plane (measured from
/// the phase of renders with thickness 0.05 and 0.1, turbulence 0.05, 0.2 and 0.5: the
/// variation scales with both). penumbra's Y is its scalar turbulence (mean -0.007, sd
/// 0.311 over a plane) mapped to those moments;
/// POV-Ray's noise is its own, so this matches in distribution only.
const IRID_TURBULENCE: (f64, f64) = (0.983, 1.93);

/// `irid`: the factor on each channel of the light reaching the surface (its diffuse
/// and its highlights alike), 1 + amount cos(2 pi d (N.L + N.V) / lambda) for film
/// thickness d. Measured on spheres lit from the camera and from aside, with povray's
/// default and chosen irid_wavelength: diffuse, phong and specular all follow it within
/// half-float precision (2e-4 relative), ambient is untouched, and the factor is not clipped.
pub fn irid_factor(
    irid: &crate::scene::Irid,
    wavelength: DVec3,
    n_dot_l: f64,
    n_dot_v: f64,
    p: DVec3,
) -> DVec3 {
    let mut d = irid.thickness;
    if irid.turbulence != 0.0 {
        let t = crate::scene::Turbulence {
            amount: DVec3::ONE,
            ..Default::default()
        };
        let y = IRID_TURBULENCE.0 + IRID_TURBULENCE.1 * super::noise::turbulence(p, &t);
        d *= 1.0 + irid.turbulence * y;
    }
    let phase = std::f64::consts::TAU * d * (n_dot_l + n_dot_v);
    DVec3::ONE + irid.amount * (DVec3::splat(phase) / wavelength).cos()
}

/// Phong: `phong * (R.L)^phong_size` with R the mirror direction of the ray.
pub fn phong_factor(phong: f64, phong_size: f64, n: DVec3, d: DVec3, l: DVec3) -> f64 {
    if phong == 0.0 {
        return 0.0;
    }
    let r = d - 2.0 * d.dot(n) * n;
    let c = r.dot(l);
    if c > 0.0 {
        phong * power(c, phong_size)
    } else {
        0.0
    }
}

/// Specular (Blinn): H = (V + L)/2, `specular * ((H.N)/|H|)^(1/roughness)`.
pub fn specular_factor(specular: f64, roughness: f64, n: DVec3, d: DVec3, l: DVec3) -> f64 {
    if specular == 0.0 {
        return 0.0;
    }
    let h = (l - d) * 0.5;
    let len = h.length();
    if len == 0.0 {
        return 0.0;
    }
    let c = h.dot(n) / len;
    if c > 0.0 {
        specular * power(c, 1.0 / roughness)
    } else {
        0.0
    }
}

/// The colour a highlight takes with `metallic m`: the light colour tinted towards the
/// pigment, less so at grazing angles (POV-Ray's empirical Fresnel-like curve).
pub fn metallic_tint(metallic: f64, pigment: DVec3, n_dot_l: f64) -> DVec3 {
    if metallic == 0.0 {
        return DVec3::ONE;
    }
    let x = n_dot_l.clamp(-1.0, 1.0).acos() / std::f64::consts::FRAC_PI_2;
    let f = (0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903).clamp(0.0, 1.0);
    DVec3::ONE + metallic * (1.0 - f) * (pigment - DVec3::ONE)
}

/// Reflectivity for `reflection { min, max falloff p }` (no fresnel): blends min and max by
/// (1 - cos)^p with cos = -D.N.
pub fn reflectivity(min: DVec3, max: DVec3, falloff: f64, cos_incidence: f64) -> DVec3 {
    if min == max {
        return max;
    }
    let frac = (1.0 - cos_incidence.clamp(0.0, 1.0)).powf(falloff);
    frac * max + (1.0 - frac) * min
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    #[test]
    fn diffuse_by_hand() {
        // 0.6 * 0.5^1 and 0.6 * 0.5^2; nothing below the horizon.
        assert!(close(diffuse_factor(0.6, 1.0, 0.5), 0.3));
        assert!(close(diffuse_factor(0.6, 2.0, 0.5), 0.15));
        assert_eq!(diffuse_factor(0.6, 1.0, 1e-11), 0.0);
    }

    #[test]
    fn crand_mean_as_measured() {
        // POV-Ray, pigment 0.5 with transmit 0.5 (att 0.5), ambient 0.1, diffuse 1, crand 0.3,
        // light head-on: pixels spread over [0.125, 0.275], mean 0.2001.
        let v = 0.5 * 0.1 * 0.5 + 0.5 * diffuse_term(1.0, 1.0, 1.0, 0.5, 0.3);
        assert!(close(v, 0.2));
        // Filter 0.8 (att 0.2): the noise is not scaled by the opacity; measured mean 0.0345,
        // negative pixels kept.
        let v = 0.5 * 0.1 * 0.2 + 0.5 * diffuse_term(1.0, 1.0, 1.0, 0.2, 0.3);
        assert!(close(v, 0.035));
        // diffuse 0.4, crand 1, opaque: measured mean -0.0011 (ambient 0.05 included).
        let v = 0.05 + 0.5 * diffuse_term(0.4, 1.0, 1.0, 1.0, 1.0);
        assert!(close(v, 0.0));
        // No diffuse light (diffuse 0, or the light behind): no noise either.
        assert_eq!(diffuse_term(0.0, 1.0, 1.0, 1.0, 1.0), 0.0);
        assert_eq!(diffuse_term(1.0, 1.0, -0.5, 1.0, 1.0), 0.0);
    }

    #[test]
    fn metallic_reflection_as_measured() {
        // POV-Ray, `reflection { 0.8 metallic }` on pigment <1, 0.5, 0> before a white sky:
        // blue 0.3481 where cos(incidence) = 0.095, 0 head-on; with metallic 0.5 green 0.6001
        // head-on. The tint is the highlights' one, with cos(incidence) for N.L.
        let c = DVec3::new(1.0, 0.5, 0.0);
        let x = (0.8 * metallic_tint(1.0, c, 0.095)).z;
        assert!((x - 0.3481).abs() < 5e-4, "{x}");
        assert!((0.8 * metallic_tint(1.0, c, 1.0)).z.abs() < 1e-4);
        assert!(((0.8 * metallic_tint(0.5, c, 1.0)).y - 0.6001).abs() < 5e-4);
    }

    #[test]
    fn phong_by_hand() {
        // Ray straight down onto an upward normal reflects straight up.
        let n = DVec3::Y;
        let d = -DVec3::Y;
        assert!(close(phong_factor(0.8, 40.0, n, d, DVec3::Y), 0.8));
        // Light at 60 degrees from the reflected ray: 0.8 * 0.5^2.
        let l = DVec3::new(3f64.sqrt() / 2.0, 0.5, 0.0);
        assert!(close(phong_factor(0.8, 2.0, n, d, l), 0.2));
        assert_eq!(phong_factor(0.8, 2.0, n, d, -DVec3::Y), 0.0);
    }

    #[test]
    fn specular_by_hand() {
        // V = L = N: H.N/|H| = 1, so the full value.
        let n = DVec3::Y;
        assert!(close(
            specular_factor(0.5, 0.05, n, -DVec3::Y, DVec3::Y),
            0.5
        ));
        // V along N, L at 90 degrees: the half vector is at 45 degrees; cos = 1/sqrt 2;
        // exponent 1/roughness = 2 gives 0.5 * 0.5.
        let s = specular_factor(0.5, 0.5, n, -DVec3::Y, DVec3::X);
        assert!(close(s, 0.25), "{s}");
    }

    #[test]
    fn metallic_tint_by_hand() {
        // Head-on (x = 0): F = 0.014567225/1.2544 - 0.011612903 = 0.0000000... about 0;
        // the highlight takes nearly the full pigment colour.
        let c = DVec3::new(1.0, 0.5, 0.0);
        let t = metallic_tint(1.0, c, 1.0);
        let f = (0.014567225 / (1.12f64 * 1.12) - 0.011612903).clamp(0.0, 1.0);
        assert!(close(t.y, 1.0 + (1.0 - f) * -0.5));
        assert_eq!(metallic_tint(0.0, c, 1.0), DVec3::ONE);
    }

    #[test]
    fn reflection_falloff_by_hand() {
        let r = reflectivity(DVec3::splat(0.1), DVec3::splat(0.9), 2.0, 0.5);
        // frac = 0.5^2 = 0.25: 0.25*0.9 + 0.75*0.1 = 0.3.
        assert!(close(r.x, 0.3));
    }
}

#[cfg(test)]
mod irid_tests {
    use super::*;

    #[test]
    fn irid_turbulence_moments_as_measured() {
        // povray's Y (see IRID_TURBULENCE): mean 0.97, sd 0.60 over a plane.
        let (mut s, mut s2, n) = (0.0, 0.0, 40_000);
        for i in 0..n {
            let p = DVec3::new(f64::from(i % 200) * 0.1, f64::from(i / 200) * 0.1, 0.0);
            let t = crate::scene::Turbulence {
                amount: DVec3::ONE,
                ..Default::default()
            };
            let y =
                IRID_TURBULENCE.0 + IRID_TURBULENCE.1 * crate::appearance::noise::turbulence(p, &t);
            s += y;
            s2 += y * y;
        }
        let mean = s / f64::from(n);
        let sd = (s2 / f64::from(n) - mean * mean).sqrt();
        assert!(
            (mean - 0.97).abs() < 0.05 && (sd - 0.60).abs() < 0.05,
            "{mean} {sd}"
        );
    }
}
