//! The fractal patterns `mandel`, `julia` and `magnet`: escape-time iterations in the x-y
//! plane (x real, y imaginary; z is ignored). Everything here was measured against POV-Ray
//! 3.7's `function { pattern { ... } }` printed to 9 digits at thousands of points (exact
//! agreement, tests below and docs/appearance.md):
//!
//! - mandel starts at z = c (the point) and julia at z = the point, iterating
//!   `z^exponent + c` until |z|^2 > 4; magnet mandel starts at z = 0 with c the point,
//!   magnet julia at the point, and both stop when |z| > 100 or |z - 1| < 0.01 (the maps'
//!   fixed point at 1 attracts most of the plane).
//! - An escape at step i (0 for the first step) gives the exterior colouring, a point still
//!   iterating after `max_iteration` steps the interior one, each of the last z, the step
//!   and the smallest |z|^2 seen (the starting z counts, magnet mandel's 0 does not).
//! - Type 1 outside is i / max_iteration whatever the factor; type 6 inside is
//!   `x^2 + factor y^2` of the last z (so factor 1 gives |z|^2), a quirk measured as it is.

use glam::DVec2;

use crate::scene::{Fractal, FractalColouring, FractalFormula};

/// |z|^2 beyond which mandel and julia have escaped.
const POWER_BAILOUT: f64 = 4.0;
/// |z|^2 beyond which the magnet maps have escaped (measured between 99.1^2 and 100.6^2).
const MAGNET_BAILOUT: f64 = 1.0e4;
/// |z - 1|^2 below which the magnet maps have converged (measured between 0.00998^2 and
/// 0.01002^2).
const MAGNET_CONVERGED: f64 = 1.0e-4;

fn mul(a: DVec2, b: DVec2) -> DVec2 {
    DVec2::new(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x)
}

/// a / b; a zero divisor gives infinities, which count as escaped.
fn div(a: DVec2, b: DVec2) -> DVec2 {
    let d = b.length_squared();
    DVec2::new(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / d
}

/// z^n by repeated squaring (n >= 1).
fn power(z: DVec2, n: u32) -> DVec2 {
    let (mut result, mut base, mut n) = (DVec2::new(1.0, 0.0), z, n);
    while n > 0 {
        if n & 1 == 1 {
            result = mul(result, base);
        }
        base = mul(base, base);
        n >>= 1;
    }
    result
}

/// One step of the iteration.
fn step(formula: FractalFormula, z: DVec2, c: DVec2) -> DVec2 {
    let one = DVec2::new(1.0, 0.0);
    match formula {
        FractalFormula::Power(2) => mul(z, z) + c,
        FractalFormula::Power(n) => power(z, n) + c,
        // ((z^2 + c - 1) / (2z + c - 2))^2
        FractalFormula::Magnet1 => {
            let w = div(mul(z, z) + c - one, 2.0 * z + c - 2.0 * one);
            mul(w, w)
        }
        // ((z^3 + 3(c - 1)z + (c - 1)(c - 2)) / (3z^2 + 3(c - 2)z + (c - 1)(c - 2) + 1))^2
        FractalFormula::Magnet2 => {
            let (c1, c2) = (c - one, c - 2.0 * one);
            let c12 = mul(c1, c2);
            let z2 = mul(z, z);
            let top = mul(z2, z) + 3.0 * mul(c1, z) + c12;
            let bottom = 3.0 * z2 + 3.0 * mul(c2, z) + c12 + one;
            let w = div(top, bottom);
            mul(w, w)
        }
    }
}

/// Whether the orbit has left (escaped or, for magnet, converged to 1) at z. NaN leaves.
fn has_left(formula: FractalFormula, z: DVec2) -> bool {
    let r2 = z.length_squared();
    r2.is_nan()
        || match formula {
            FractalFormula::Power(_) => r2 > POWER_BAILOUT,
            FractalFormula::Magnet1 | FractalFormula::Magnet2 => {
                r2 > MAGNET_BAILOUT
                    || (z - DVec2::new(1.0, 0.0)).length_squared() < MAGNET_CONVERGED
            }
        }
}

/// The raw value at a pattern-space point (before frequency, phase and the wrap).
pub fn fractal_value(f: &Fractal, p: glam::DVec3) -> f64 {
    let point = DVec2::new(p.x, p.y);
    let (c, z, min_r2) = match (f.julia, f.formula) {
        (Some(c), _) => (DVec2::from(c), point, point.length_squared()),
        (None, FractalFormula::Power(_)) => (point, point, point.length_squared()),
        (None, _) => (point, DVec2::ZERO, f64::INFINITY),
    };
    let orbit = match f.formula {
        // The commonest formula in a loop of its own: the step and the escape test without
        // a match on the formula at each of up to max_iteration steps (animations/
        // fractalzoom: mandel 10000, 156 M instructions of 313 M at 40x30).
        FractalFormula::Power(2) => iterate(f.max_iteration, (z, min_r2), Power2 { c }),
        formula => iterate(f.max_iteration, (z, min_r2), Any { formula, c }),
    };
    let (z, min_r2) = match orbit {
        Orbit::Left(i, z) => {
            let (kind, factor) = f.exterior;
            return match kind {
                FractalColouring::Count => f64::from(i) / f64::from(f.max_iteration),
                FractalColouring::Absolute => z.length() * factor,
                _ => common_colouring(kind, factor, z),
            };
        }
        Orbit::Stayed(z, min_r2) => (z, min_r2),
    };
    let (kind, factor) = f.interior;
    match kind {
        FractalColouring::Count => min_r2.sqrt() * factor,
        FractalColouring::Absolute => z.x * z.x + factor * z.y * z.y,
        _ => common_colouring(kind, factor, z),
    }
}

/// Where an orbit ended: it left at step i with z, or stayed for every step, its last z and
/// the smallest |z|^2 seen.
enum Orbit {
    Left(u32, DVec2),
    Stayed(DVec2, f64),
}

/// One formula's step and escape test, for [`iterate`]. (The same loop given two closures
/// instead measured 17% slower: fractalzoom at 320x240 1.88-1.89 s against 1.61-1.65 s.)
trait Map {
    fn step(&self, z: DVec2) -> DVec2;
    fn has_left(&self, z: DVec2) -> bool;
}

/// z^2 + c, known when compiled.
struct Power2 {
    c: DVec2,
}

impl Map for Power2 {
    #[inline(always)]
    fn step(&self, z: DVec2) -> DVec2 {
        step(FractalFormula::Power(2), z, self.c)
    }
    #[inline(always)]
    fn has_left(&self, z: DVec2) -> bool {
        has_left(FractalFormula::Power(2), z)
    }
}

/// Any formula, chosen at each step.
struct Any {
    formula: FractalFormula,
    c: DVec2,
}

impl Map for Any {
    fn step(&self, z: DVec2) -> DVec2 {
        step(self.formula, z, self.c)
    }
    fn has_left(&self, z: DVec2) -> bool {
        has_left(self.formula, z)
    }
}

/// Up to `steps` steps of `map` from z (`min_r2`: the smallest |z|^2 so far).
#[inline(always)]
fn iterate(steps: u32, (mut z, mut min_r2): (DVec2, f64), map: impl Map) -> Orbit {
    for i in 0..steps {
        z = map.step(z);
        min_r2 = min_r2.min(z.length_squared());
        if map.has_left(z) {
            return Orbit::Left(i, z);
        }
    }
    Orbit::Stayed(z, min_r2)
}

/// The colourings that read the same inside and outside: of the last z, times the factor.
fn common_colouring(kind: FractalColouring, factor: f64, z: DVec2) -> f64 {
    factor
        * match kind {
            FractalColouring::Real => z.x,
            FractalColouring::Imaginary => z.y,
            FractalColouring::RealSquared => z.x * z.x,
            FractalColouring::ImaginarySquared => z.y * z.y,
            _ => 1.0,
        }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::scene::{Pattern, PatternKind};

    /// The final pattern value (with POV-Ray's wrap) of a fractal at (x, y).
    fn value(f: Fractal, x: f64, y: f64) -> f64 {
        let pattern = Pattern::new(PatternKind::Fractal(f));
        super::super::pattern::pattern_value(&pattern, DVec3::new(x, y, 0.0))
    }

    fn colour(n: i64) -> FractalColouring {
        FractalColouring::from_type(n).expect("type")
    }

    #[test]
    fn mandel_matches_povray_printed_values() {
        // (x, y, value) of `mandel 50` and `mandel 50 interior 1, 1`, from POV-Ray's
        // `#debug` of `function { pattern { ... } }`.
        let plain = Fractal::new(FractalFormula::Power(2), None, 50);
        for (x, y, want) in [
            (0.0, 0.0, 1.0),
            (0.5, 0.5, 0.06),
            (1.0, 1.0, 0.0),
            (-0.75, 0.1, 0.62),
            (0.26, 0.0, 0.56),
        ] {
            assert!((value(plain, x, y) - want).abs() < 1e-9, "({x}, {y})");
        }
        let inner = Fractal {
            interior: (colour(1), 1.0),
            ..plain
        };
        for (x, y, want) in [
            (-0.5, 0.2, 0.29),
            (0.3, 0.5, 0.105_025_743),
            (0.0, 0.0, 0.0),
        ] {
            assert!((value(inner, x, y) - want).abs() < 1e-8, "({x}, {y})");
        }
    }

    #[test]
    fn colourings_and_exponents_match_povray() {
        // `mandel 30 exterior T, 0.7 interior T, 0.9` for T = 2 .. 6 and exterior 1 (whose
        // factor POV-Ray ignores), and julia with exponents, at points read back from POV-Ray.
        let base = Fractal::new(FractalFormula::Power(2), None, 30);
        let typed = |t: i64| Fractal {
            exterior: (colour(t), 0.7),
            interior: (colour(t), 0.9),
            ..base
        };
        for (t, x, y, want) in [
            (1, 0.3968, -0.6368, 0.2),
            (1, 0.0154, 0.7507, 0.366_666_667),
            (2, -1.7432, 0.9033, 0.335_716_745),
            (2, 0.3968, -0.6368, 0.656_540_727),
            (2, 0.0154, 0.7507, 0.473_905_001),
            (3, -1.7432, 0.9033, 0.427_834_416),
            (4, 0.0154, 0.7507, 0.327_107_81),
            (5, 0.3968, -0.6368, 0.870_901_377),
            (6, -1.7432, 0.9033, 0.607_609_918),
            (6, -0.5155, -0.1313, 0.148_050_569),
        ] {
            let v = value(typed(t), x, y);
            assert!(
                (v - want).abs() < 2e-9,
                "type {t} at ({x}, {y}): {v} vs {want}"
            );
        }
    }

    #[test]
    fn magnet_matches_povray_printed_values() {
        // `magnet 1 mandel 40`: (x, y, value); `magnet 1 mandel 40 exterior 6, 0.001`.
        let m1 = Fractal::new(FractalFormula::Magnet1, None, 40);
        for (x, y, want) in [
            (-1.3342, 0.2654, 0.075),
            (-0.4103, 0.6235, 0.275),
            (0.6623, 1.4475, 1.0),
        ] {
            assert!((value(m1, x, y) - want).abs() < 1e-9, "({x}, {y})");
        }
        let abs = Fractal {
            exterior: (colour(6), 0.001),
            ..m1
        };
        for (x, y, want) in [
            (-1.3342, 0.2654, 0.000_998_677),
            (2.8552, -0.1419, 0.142_659_05),
        ] {
            assert!((value(abs, x, y) - want).abs() < 1e-9, "({x}, {y})");
        }
        // `magnet 2 mandel 40`, and with `interior 1, 1 exterior 6, 1`.
        let m2 = Fractal::new(FractalFormula::Magnet2, None, 40);
        let m2_abs = Fractal {
            exterior: (colour(6), 1.0),
            interior: (colour(1), 1.0),
            ..m2
        };
        // `magnet 1 julia <0.5, 0.4>, 40`; `magnet 2 julia <0.5, 0.4>, 40 interior 6, 1
        // exterior 2, 1`.
        let j1 = Fractal::new(FractalFormula::Magnet1, Some([0.5, 0.4]), 40);
        let j2 = Fractal {
            exterior: (colour(2), 1.0),
            interior: (colour(6), 1.0),
            ..Fractal::new(FractalFormula::Magnet2, Some([0.5, 0.4]), 40)
        };
        for (f, x, y, want) in [
            (m2, -1.3342, 0.2654, 0.025),
            (m2, 2.3076, 0.5466, 0.1),
            (m2_abs, -1.3342, 0.2654, 0.994_838_294),
            (m2_abs, -0.4103, 0.6235, 0.999_996_088),
            (j1, 3.9695, -0.1784, 0.075),
            (j1, 2.6267, -1.5678, 0.175),
            (j2, 3.6669, 0.4745, 0.000_004_741),
            (j2, 2.0318, 2.2729, 1.000_007_881),
        ] {
            // POV-Ray prints values in (1, 1.00001) as they are; penumbra's pipeline stops
            // at 1, which a colour map reads the same.
            let (v, want) = (value(f, x, y), f64::min(want, 1.0));
            assert!((v - want).abs() < 2e-9, "({x}, {y}): {v} vs {want}");
        }
    }

    #[test]
    fn julia_and_exponents_match_povray() {
        // `julia <-0.7, 0.3>, 40 exponent E exterior T, 0.8 interior T, 0.6` and `mandel 40
        // exponent 4 exterior 1, 0.8 interior 1, 0.6`.
        let julia = |e: u32, t: i64| Fractal {
            exterior: (colour(t), 0.8),
            interior: (colour(t), 0.6),
            ..Fractal::new(FractalFormula::Power(e), Some([-0.7, 0.3]), 40)
        };
        let mandel4 = Fractal {
            exterior: (colour(1), 0.8),
            interior: (colour(1), 0.6),
            ..Fractal::new(FractalFormula::Power(4), None, 40)
        };
        for (f, x, y, want) in [
            (julia(3, 2), -0.9336, 0.2307, 0.006_741_669),
            (julia(3, 2), 1.0736, 0.6135, 0.460_158_094),
            (julia(3, 2), 0.5431, -0.4988, 0.736_445_095),
            (julia(5, 6), -1.5629, -0.0922, 0.000_919_238),
            (julia(5, 6), -1.419, -1.0793, 0.881_559_536),
            (mandel4, 0.7501, 1.0571, 0.025),
            (mandel4, 0.0136, 0.0461, 0.028_836_109),
            (mandel4, 0.0842, -0.0583, 0.061_431_823),
        ] {
            let v = value(f, x, y);
            assert!((v - want).abs() < 2e-9, "({x}, {y}): {v} vs {want}");
        }
    }
}
