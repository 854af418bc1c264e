//! Surfaces around curves given by a quartic in y (51, 52), fitted to POV-Ray's values.

use std::f64::consts::TAU;

use glam::DVec3;

/// The most tubes f_polytubes draws: each costs a distance, and more than this many are
/// indistinguishable from a solid of revolution anyway.
const MAX_TUBES: f64 = 1024.0;

fn quartic(y: f64, c: &[f64]) -> f64 {
    (((c[4] * y + c[3]) * y + c[2]) * y + c[1]) * y + c[0]
}

/// 51: ρ - q(y), the surface of revolution of radius q(y) = P0 + P1 y + ... + P4 y⁴.
pub fn poly4(p: DVec3, a: &[f64]) -> f64 {
    p.x.hypot(p.z) - quartic(p.y, a)
}

/// 52: the distance in the horizontal plane to the nearest of ⌊P0⌋ curves x = q(y) sin θ,
/// z = q(y) cos θ, θ = 2πi / P0 (P0 itself, not its integer part, divides the turn), q
/// from P1..P5 as in f_poly4. With no tubes POV-Ray gives 10000.
pub fn polytubes(p: DVec3, a: &[f64]) -> f64 {
    let n = a[0];
    let q = quartic(p.y, &a[1..]);
    let count = n.min(MAX_TUBES);
    let mut best: f64 = 10000.0;
    let mut i = 0.0;
    while i + 1.0 <= count {
        let (s, c) = (TAU * i / n).sin_cos();
        best = best.min((p.x - q * s).hypot(p.z - q * c));
        i += 1.0;
    }
    best
}
