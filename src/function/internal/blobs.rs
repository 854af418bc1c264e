//! Sums of blob-like components (6, 7, 10, 19, 32, 62, 63), fitted to POV-Ray's printed
//! values. Several are built from the same three ellipsoids, one along each axis:
//! Qᵢ = e r² + (1 - e) xᵢ², round for e = 1, prolate along axis i for e < 1.

use glam::DVec3;

/// e r² + (1 - e) xᵢ² for i = x, y, z.
fn ellipsoids(p: DVec3, e: f64) -> [f64; 3] {
    let r2 = p.length_squared();
    [p.x, p.y, p.z].map(|c| e * r2 + (1.0 - e) * c * c)
}

/// POV-Ray's blob component: s (1 - k²r²)² inside radius 1/k, 0 outside.
fn component(r2: f64, s: f64, k: f64) -> f64 {
    let t = 1.0 - k * k * r2;
    if t > 0.0 { s * t * t } else { 0.0 }
}

/// 6: minus two blob components at x = ∓P0/2, strengths P1 and P3, inverse radii P2, P4.
pub fn blob(p: DVec3, a: &[f64]) -> f64 {
    let half = DVec3::new(a[0] / 2.0, 0.0, 0.0);
    let first = component((p + half).length_squared(), a[1], a[2]);
    let second = component((p - half).length_squared(), a[3], a[4]);
    -(first + second)
}

/// 7: P3 - P2 (e^(-P1 r₀²) + e^(-P1 r₁²)), the distances from the origin and from (P0, 0, 0).
pub fn blob2(p: DVec3, a: &[f64]) -> f64 {
    let other = p - DVec3::new(a[0], 0.0, 0.0);
    let k = a[1];
    a[3] - a[2] * ((-k * p.length_squared()).exp() + (-k * other.length_squared()).exp())
}

/// 10 (union, the nearest ellipsoid) and 32 (intersection, the farthest):
/// P3 - P2 e^(-P1 Q), P0 the eccentricity.
pub fn crossed_ellipsoids(p: DVec3, a: &[f64], intersect: bool) -> f64 {
    let [qx, qy, qz] = ellipsoids(p, a[0]);
    let q = if intersect {
        qx.max(qy).max(qz)
    } else {
        qx.min(qy).min(qz)
    };
    a[3] - a[2] * (-a[1] * q).exp()
}

/// 19: P3 - P2 Σ e^(-P1 Qᵢ), P0 the spikiness (the eccentricity).
pub fn flange_cover(p: DVec3, a: &[f64]) -> f64 {
    let sum: f64 = ellipsoids(p, a[0]).iter().map(|q| (-a[1] * q).exp()).sum();
    a[3] - a[2] * sum
}

/// 62: P2 (Σ e^(-P1 Qᵢ) - P4 e^(-P3 r²)), P0 the spikiness (the eccentricity).
pub fn spikes(p: DVec3, a: &[f64]) -> f64 {
    let sum: f64 = ellipsoids(p, a[0]).iter().map(|q| (-a[1] * q).exp()).sum();
    a[2] * (sum - a[4] * (-a[3] * p.length_squared()).exp())
}

/// 63: y - P0 cos(P1 x) cos(P2 z) e^(-P3 (x² + z²)).
pub fn spikes_2d(p: DVec3, a: &[f64]) -> f64 {
    let fall = (-a[3] * (p.x * p.x + p.z * p.z)).exp();
    p.y - a[0] * (a[1] * p.x).cos() * (a[2] * p.z).cos() * fall
}
