//! The 2-D curves of functions.inc, made surfaces by extruding them along z or, when the
//! "SOR switch" is positive, by turning them about y. The last three parameters are that
//! switch, an offset and an angle: turned curves are read at (ρ - offset, y) rotated by the
//! angle in degrees, where ρ = √(x² + z²); extruded curves at (x, y), the offset and angle
//! unused (measured: they change nothing). Like the surfaces in algebraic.rs the field
//! strength P0 multiplies the polynomial, and the product is clamped to [-10, 10], except
//! for f_algbr_cyl1..4 whose P1 is that limit ("field limit"). Every polynomial was fitted
//! to POV-Ray's printed values at random points and checked at others.

use glam::{DVec2, DVec3};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Curve {
    /// 0: y² + |x|³ - x².
    AlgbrCyl1,
    /// 1: 2y³ + 3x²y - y² - y⁴ - 2x⁴.
    AlgbrCyl2,
    /// 2: xy² + 2x²y - y² - x²y² - x⁴.
    AlgbrCyl3,
    /// 3: y³ - 3x²y - y⁴ - 2x²y² - x⁴.
    AlgbrCyl4,
    /// 15: y⁴ - x⁴ + a²x² - b²y²; a, b = P1, P2 (x and y factors).
    Devils,
    /// 21: (4a - b) xy² - y² - (b + 1) x²: f_folium_surface's section at z = 0, negated.
    Folium,
    /// 34: b²x⁴ - ab³x² - y²; a = P1 (dimple), b = P2 (closeness).
    Kampyle,
    /// 39: a²b²x² - b²x⁴ - y²; a = P1 (size), b = P2 (width).
    Lemniscate,
    /// 50: c² (ax³ + bx⁴) - y²; a, b, c = P1..P3.
    Piriform,
    /// 67: xy² + c²x³ + ac²x² - by², f_strophoid's section at z = 0.
    Strophoid,
    /// 75: b - y (x² + a²); a = P1 (size), b = P2 (height).
    Witch,
}

/// The clamp on the curves other than f_algbr_cyl1..4.
const FIELD_LIMIT: f64 = 10.0;

impl Curve {
    /// How many parameters the curve itself takes between P0 and the SOR switch.
    pub fn parameters(self) -> usize {
        match self {
            Curve::AlgbrCyl1 | Curve::AlgbrCyl2 | Curve::AlgbrCyl3 | Curve::AlgbrCyl4 => 1,
            Curve::Piriform | Curve::Strophoid => 3,
            _ => 2,
        }
    }

    pub fn eval(self, p: DVec3, a: &[f64]) -> f64 {
        let k = self.parameters();
        let q = section(p, a[k + 1], a[k + 2], a[k + 3]);
        let v = a[0] * self.polynomial(q, &a[1..=k]);
        let limit = match self {
            Curve::AlgbrCyl1 | Curve::AlgbrCyl2 | Curve::AlgbrCyl3 | Curve::AlgbrCyl4 => a[1],
            _ => FIELD_LIMIT,
        };
        // Not f64::clamp: a negative limit must not panic. (POV-Ray's result for one is
        // not reproduced.)
        v.min(limit).max(-limit)
    }

    fn polynomial(self, q: DVec2, a: &[f64]) -> f64 {
        let DVec2 { x, y } = q;
        let (x2, y2) = (x * x, y * y);
        match self {
            Curve::AlgbrCyl1 => y2 + x2 * x.abs() - x2,
            Curve::AlgbrCyl2 => 2.0 * y2 * y + 3.0 * x2 * y - y2 - y2 * y2 - 2.0 * x2 * x2,
            Curve::AlgbrCyl3 => x * y2 + 2.0 * x2 * y - y2 - x2 * y2 - x2 * x2,
            Curve::AlgbrCyl4 => y2 * y - 3.0 * x2 * y - y2 * y2 - 2.0 * x2 * y2 - x2 * x2,
            Curve::Devils => y2 * y2 - x2 * x2 + a[0] * a[0] * x2 - a[1] * a[1] * y2,
            Curve::Folium => (4.0 * a[0] - a[1]) * x * y2 - y2 - (a[1] + 1.0) * x2,
            Curve::Kampyle => {
                let b2 = a[1] * a[1];
                b2 * x2 * x2 - a[0] * b2 * a[1] * x2 - y2
            }
            Curve::Lemniscate => {
                let b2 = a[1] * a[1];
                a[0] * a[0] * b2 * x2 - b2 * x2 * x2 - y2
            }
            Curve::Piriform => a[2] * a[2] * (a[0] * x2 * x + a[1] * x2 * x2) - y2,
            Curve::Strophoid => {
                let c2 = a[2] * a[2];
                x * y2 + c2 * x2 * x + a[0] * c2 * x2 - a[1] * y2
            }
            Curve::Witch => a[1] - y * (x2 + a[0] * a[0]),
        }
    }
}

/// Where the curve is read for the point `p`.
fn section(p: DVec3, switch: f64, offset: f64, degrees: f64) -> DVec2 {
    if switch > 0.0 {
        let u = p.x.hypot(p.z) - offset;
        let (s, c) = degrees.to_radians().sin_cos();
        DVec2::new(u * c - p.y * s, u * s + p.y * c)
    } else {
        DVec2::new(p.x, p.y)
    }
}
