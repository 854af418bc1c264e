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

/// 40: a woven mesh of threads along x, P1 apart in z, and along z, P0 apart in x. Thread k
/// of each family rises and falls as ±P3 cos(π t / spacing) along its length t, the sign
/// alternating with k and opposite between the two families, so that they pass over and
/// under each other. The value is the distance to the nearest thread, horizontal offsets
/// times P2 and vertical ones times P4. Of each family only the two threads either side
/// of the point can be nearest: the next ones rise like those, only farther away.
/// (POV-Ray's values for negative spacings differ; they are not reproduced.)
pub fn mesh1(p: DVec3, a: &[f64]) -> f64 {
    let (dx, dz, across, amplitude, vertical) = (a[0], a[1], a[2], a[3], a[4]);
    let family = |along: f64, across_at: f64, spacing: f64, other: f64, sign: f64| {
        let k = (across_at / spacing).floor();
        let wave = amplitude * (std::f64::consts::PI * along / other).cos();
        [k, k + 1.0]
            .map(|k| {
                let parity = if k.rem_euclid(2.0) == 0.0 { 1.0 } else { -1.0 };
                let rise = p.y - sign * parity * wave;
                ((across_at - k * spacing) * across).hypot(rise * vertical)
            })
            .into_iter()
            .fold(f64::INFINITY, f64::min)
    };
    let along_x = family(p.x, p.z, dz, dx, 1.0);
    let along_z = family(p.z, p.x, dx, dz, -1.0);
    along_x.min(along_z)
}
