//! The algebraic surfaces of functions.inc whose first parameter is a field strength:
//! POV-Ray multiplies the polynomial by it and clamps the product to [-10, 10] (measured:
//! far from the surface every one of them reads exactly ±10, whatever the strength).
//! Each polynomial was recovered by a least-squares fit over POV-Ray's printed values at
//! random points, exact to the printed digits, then checked at other random points and
//! parameters; where the classic surface is recognisable it is written in that form.

use glam::DVec3;

/// POV-Ray's clamp on field-strength functions.
const FIELD_LIMIT: f64 = 10.0;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Field {
    /// 4: y²(a² - ρ²) - (ρ² + 2ay - a²)², ρ² = x² + z², the bicorn turned about y; a = P1.
    Bicorn,
    /// 5: a y ρ² - r⁴ (the bifolium turned about y); a = P1.
    Bifolia,
    /// 8: Boy's surface in its classic sextic form, times P1 (functions.inc calls P1 a scale,
    /// but POV-Ray multiplies by it).
    BoySurface,
    /// 11: x²z² - y.
    CrossedTrough,
    /// 12: z + y³ - x³.
    CubicSaddle,
    /// 13 and 43 (f_odd prints the same values as f_cushion everywhere measured).
    Cushion,
    /// 14: y⁴ - y²/4 - (x² + z²)² + 0.36 x².
    DevilsCurve,
    /// 16: a torus about y (radii a = P1, b = P2, centre (P3, P4, 0)) inverted in the sphere of
    /// radius k = P5 at the origin, its quartic negated. POV-Ray's has one term more than the
    /// inversion gives, 8 (a² - b²) k² P4 y r² (measured; it only matters for P4 ≠ 0).
    DupinCyclid,
    /// 20: y² + z² + (b + 1) x² - (4a - b) x (y² + z²); a = P1 (neck), b = P2 (divergence).
    FoliumSurface,
    /// 22: x⁴ (1 + x) / 2 - y² - z².
    Glob,
    /// 23: the heart surface, -((2x² + y² + z² - 1)³ - x²z³/10 - y²z³).
    Heart,
    /// 30: Hunt's surface, -(4 (r² - 13)³ + 27 (3x² + y² - 4z² - 12)²).
    HuntSurface,
    /// 31: -(x² + y² - z²)² + 2(a² + b²)(x² - z²) - 2(a² - b²)y² - (a² - b²)²; a = P1 (major
    /// radius), b = P2 (minor).
    HyperbolicTorus,
    /// 33: b²x⁴ - a²b²x² - y² - z²; a = P1 (dimple), b = P2 (closeness).
    KampyleOfEudoxus,
    /// 35: the classic sextic of the Klein bottle, -((r² + 2y - 1)((r² - 2y - 1)² - 8z²) +
    /// 16xz (r² - 2y - 1)).
    KleinBottle,
    /// 36: Kummer's quartic, r² - 1 + x²y² + x²z² + y²z² - (x⁴ + y⁴ + z⁴).
    KummerV1,
    /// 37: 1 - a r² - c xyz - (x⁴ + y⁴ + z⁴) - b (x²y² + x²z² + y²z²); a, b, c = P1..P3.
    KummerV2,
    /// 38: x² - x⁴ - y² - z².
    LemniscateOfGerono,
    /// 41: y² (1 - y² - z²) - 4x² r².
    Mitre,
    /// 42: 6yz - y³ - z³.
    NodalCubic,
    /// 44: -r⁴ + a²(c - 2)(x² + z²) - 2a²y² - a⁴ + b²; a, b, c = P1..P3.
    OvalsOfCassini,
    /// 45: y - x² - z².
    Paraboloid,
    /// 46: -(x² + y² - z)² + (a² + b²)(x² - z) - (a² - b²)y² - (a² - b²)²; a = P1 (major
    /// radius), b = P2 (minor).
    ParabolicTorus,
    /// 48: x⁴ + y⁴ + z⁴ - r².
    Pillow,
    /// 49: x⁴ - x³ + y² + z².
    Piriform,
    /// 54: y - x⁴ - z⁴.
    QuarticParaboloid,
    /// 55: y + z⁴ - x⁴.
    QuarticSaddle,
    /// 56: a²b² - (b² + y²)(x² + z²); a = P1 (egg diameter), b = P2 (tube width).
    QuarticCylinder,
    /// 65: Steiner's Roman surface, -(x²y² + x²z² + y²z² + xyz).
    SteinersRoman,
    /// 66: x (y² + z²) + c²x³ + a c² x² - b (y² + z²); a, b, c = P1..P3.
    Strophoid,
    /// 71: the quartic torus about y, negated; major radius P1, minor P2.
    Torus2,
    /// 72: -(4r⁴ - 20r² + 17 + 9x²(y² + z²)).
    TorusGumdrop,
    /// 73: yz² - x².
    Umbrella,
    /// 74: a (1 - y) - y (x² + z²); a = P1.
    WitchOfAgnesi,
}

impl Field {
    /// The clamped field at `p`; `a` holds the field strength and then the other parameters.
    pub fn eval(self, p: DVec3, a: &[f64]) -> f64 {
        (a[0] * self.polynomial(p, &a[1..])).clamp(-FIELD_LIMIT, FIELD_LIMIT)
    }

    fn polynomial(self, p: DVec3, a: &[f64]) -> f64 {
        let DVec3 { x, y, z } = p;
        let (x2, y2, z2) = (x * x, y * y, z * z);
        let r2 = x2 + y2 + z2;
        let rho2 = x2 + z2;
        match self {
            Field::Bicorn => {
                let s = a[0];
                let t = rho2 + 2.0 * s * y - s * s;
                y2 * (s * s - rho2) - t * t
            }
            Field::BoySurface => a[0] * boy(x, y, z),
            Field::DupinCyclid => dupin(p, a),
            Field::Bifolia => a[0] * y * rho2 - r2 * r2,
            Field::CrossedTrough => x2 * z2 - y,
            Field::CubicSaddle => z + y2 * y - x2 * x,
            Field::Cushion => cushion(x2, y2, z, z2),
            Field::DevilsCurve => y2 * y2 - 0.25 * y2 - rho2 * rho2 + 0.36 * x2,
            Field::FoliumSurface => {
                let yz = y2 + z2;
                yz + (a[1] + 1.0) * x2 - (4.0 * a[0] - a[1]) * x * yz
            }
            Field::Glob => 0.5 * x2 * x2 * (1.0 + x) - y2 - z2,
            Field::Heart => {
                let t = 2.0 * x2 + y2 + z2 - 1.0;
                -(t * t * t - 0.1 * x2 * z2 * z - y2 * z2 * z)
            }
            Field::HuntSurface => {
                let t = r2 - 13.0;
                let u = 3.0 * x2 + y2 - 4.0 * z2 - 12.0;
                -(4.0 * t * t * t + 27.0 * u * u)
            }
            Field::HyperbolicTorus => {
                let (s, d) = sum_difference(a[0], a[1]);
                let t = x2 + y2 - z2;
                -t * t + 2.0 * s * (x2 - z2) - 2.0 * d * y2 - d * d
            }
            Field::KampyleOfEudoxus => {
                let (b2, a2) = (a[1] * a[1], a[0] * a[0]);
                b2 * x2 * x2 - a2 * b2 * x2 - y2 - z2
            }
            Field::KleinBottle => {
                let u = r2 + 2.0 * y - 1.0;
                let v = r2 - 2.0 * y - 1.0;
                -(u * (v * v - 8.0 * z2) + 16.0 * x * z * v)
            }
            Field::KummerV1 => {
                -(x2 * x2 + y2 * y2 + z2 * z2) + x2 * y2 + x2 * z2 + y2 * z2 + r2 - 1.0
            }
            Field::KummerV2 => {
                1.0 - a[0] * r2
                    - a[2] * x * y * z
                    - (x2 * x2 + y2 * y2 + z2 * z2)
                    - a[1] * (x2 * y2 + x2 * z2 + y2 * z2)
            }
            Field::LemniscateOfGerono => x2 - x2 * x2 - y2 - z2,
            Field::Mitre => y2 * (1.0 - y2 - z2) - 4.0 * x2 * r2,
            Field::NodalCubic => 6.0 * y * z - y2 * y - z2 * z,
            Field::OvalsOfCassini => {
                let s2 = a[0] * a[0];
                -r2 * r2 + s2 * (a[2] - 2.0) * rho2 - 2.0 * s2 * y2 - s2 * s2 + a[1] * a[1]
            }
            Field::Paraboloid => y - x2 - z2,
            Field::ParabolicTorus => {
                let (s, d) = sum_difference(a[0], a[1]);
                let t = x2 + y2 - z;
                -t * t + s * (x2 - z) - d * y2 - d * d
            }
            Field::Pillow => x2 * x2 + y2 * y2 + z2 * z2 - r2,
            Field::Piriform => x2 * x2 - x2 * x + y2 + z2,
            Field::QuarticParaboloid => y - x2 * x2 - z2 * z2,
            Field::QuarticSaddle => y + z2 * z2 - x2 * x2,
            Field::QuarticCylinder => {
                let b2 = a[1] * a[1];
                a[0] * a[0] * b2 - (b2 + y2) * rho2
            }
            Field::SteinersRoman => -(x2 * y2 + x2 * z2 + y2 * z2 + x * y * z),
            Field::Strophoid => {
                let c2 = a[2] * a[2];
                let yz = y2 + z2;
                x * yz + c2 * x2 * x + a[0] * c2 * x2 - a[1] * yz
            }
            Field::Torus2 => {
                let (big, small) = (a[0] * a[0], a[1] * a[1]);
                let t = r2 + big - small;
                -(t * t - 4.0 * big * rho2)
            }
            Field::TorusGumdrop => -(4.0 * r2 * r2 - 20.0 * r2 + 17.0 + 9.0 * x2 * (y2 + z2)),
            Field::Umbrella => y * z2 - x2,
            Field::WitchOfAgnesi => a[0] * (1.0 - y) - y * rho2,
        }
    }
}

/// a² + b² and a² - b², how both tori take their radii.
fn sum_difference(a: f64, b: f64) -> (f64, f64) {
    (a * a + b * b, a * a - b * b)
}

/// The fitted quartic; it has no tidier factored form that we know of.
fn cushion(x2: f64, y2: f64, z: f64, z2: f64) -> f64 {
    x2 + y2 - 2.0 * z2 + 2.0 * z2 * z + 2.0 * y2 * z - z2 * z2 - y2 * z2 - y2 * y2 + x2 * z2
        - 2.0 * x2 * y2
        - x2 * x2
}

/// Boy's surface, 64 (1 - z)³z³ - 48 (1 - z)²z² (3x² + 3y² + 2z²) + 12 (1 - z) z (27 ρ⁴ -
/// 24 z²ρ² + 36√2 yz (y² - 3x²) + 4z⁴) + (9ρ² - 2z²)(-81 ρ⁴ - 72 z²ρ² + 108√2 xz (x² - 3y²)
/// + 4z⁴), ρ² = x² + y².
fn boy(x: f64, y: f64, z: f64) -> f64 {
    let (x2, y2, z2) = (x * x, y * y, z * z);
    let rho2 = x2 + y2;
    let w = 1.0 - z;
    let sqrt2 = std::f64::consts::SQRT_2;
    let zw = z * w;
    64.0 * zw * zw * zw - 48.0 * zw * zw * (3.0 * rho2 + 2.0 * z2)
        + 12.0
            * zw
            * (27.0 * rho2 * rho2 - 24.0 * z2 * rho2
                + 36.0 * sqrt2 * y * z * (y2 - 3.0 * x2)
                + 4.0 * z2 * z2)
        + (9.0 * rho2 - 2.0 * z2)
            * (-81.0 * rho2 * rho2 - 72.0 * z2 * rho2
                + 108.0 * sqrt2 * x * z * (x2 - 3.0 * y2)
                + 4.0 * z2 * z2)
}

/// The Dupin cyclide's quartic: the torus (|q - c|² + a² - b²)² - 4a²((qx - cx)² + qz²) at
/// q = k²p / |p|², times |p|⁴, with POV-Ray's extra term.
fn dupin(p: DVec3, a: &[f64]) -> f64 {
    let (major, minor, cx, cy, k) = (a[0], a[1], a[2], a[3], a[4]);
    let r2 = p.length_squared();
    let k2 = k * k;
    let shape = major * major - minor * minor;
    let t = k2 * k2 - 2.0 * k2 * (p.x * cx + p.y * cy) + (cx * cx + cy * cy + shape) * r2;
    let across = k2 * p.x - cx * r2;
    let v = t * t - 4.0 * major * major * (across * across + k2 * k2 * p.z * p.z);
    -(v + 8.0 * shape * k2 * cy * p.y * r2)
}
