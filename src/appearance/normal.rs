//! Normal perturbation as POV-Ray does it for patterns used as normals: the pattern is
//! sampled at the four corners of a small tetrahedron (size `accuracy`, in pattern space)
//! and the normal is tilted against the weighted sum. Measured with povray on a plane:
//! `normal { gradient x, A }` tilts the normal by -0.1333 A per unit slope whatever the
//! pattern's scale, which is 5 A times the tetrahedral sum (4/3 * 0.02 * slope).

use glam::DVec3;

use super::pattern::pattern_value;
use crate::scene::Normal;

/// The corners of a regular tetrahedron in pattern space, oriented as POV-Ray's are: one
/// corner along +y, one in the xy plane towards +x. The orientation matters only where the
/// pattern jumps: the groove a jump leaves spans x in [-0.943, +0.471] * accuracy (measured
/// on `gradient x` with povray, two levels split at the jump). Their outer products sum to
/// 4/3 I, so smooth patterns do not see the orientation.
const TETRAHEDRON: [DVec3; 4] = [
    DVec3::new(0.942_809_041_582_063_4, -1.0 / 3.0, 0.0),
    DVec3::new(-0.471_404_520_791_031_7, -1.0 / 3.0, 0.816_496_580_927_726),
    DVec3::new(-0.471_404_520_791_031_7, -1.0 / 3.0, -0.816_496_580_927_726),
    DVec3::new(0.0, 1.0, 0.0),
];
/// POV-Ray's gain on the tetrahedral sum.
const GAIN: f64 = 5.0;

/// The unit normal `n` (world space) tilted by `normal` at world point `p`.
pub fn perturb(normal: &Normal, p: DVec3, n: DVec3) -> DVec3 {
    if normal.amount == 0.0 {
        return n;
    }
    let q = normal.transform.inverse_point(p);
    let mut sum = DVec3::ZERO;
    for v in TETRAHEDRON {
        sum += pattern_value(&normal.pattern, q + v * normal.accuracy) * v;
    }
    let tilt = -GAIN * normal.amount * sum;
    let len = tilt.length();
    if len == 0.0 || !len.is_finite() {
        return n;
    }
    // The tilt keeps its pattern-space length: POV-Ray's result does not change with the
    // pattern's scale, only its direction follows the transform.
    let world = normal.transform.normal(tilt).normalize_or_zero() * len;
    (n + world).normalize_or(n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Transform;
    use crate::scene::{Pattern, PatternKind};

    #[test]
    fn gradient_normal_matches_povray_probe() {
        // povray: plane facing -z, light along the view: N.L = 0.9978 for amount 0.5,
        // 0.9912 for amount 1, independent of `scale 2`.
        let mut nor = Normal::new(Pattern::new(PatternKind::Gradient(DVec3::X)));
        let n = -DVec3::Z;
        for (amount, expect) in [(0.5, 0.9978), (1.0, 0.9912)] {
            nor.amount = amount;
            let p = DVec3::new(0.3, 0.1, 0.0);
            let m = perturb(&nor, p, n);
            assert!((m.dot(n) - expect).abs() < 2e-4, "{}", m.dot(n));
            // Tilted towards -x.
            assert!(m.x < 0.0);
        }
        nor.transform_by(&Transform::scale(DVec3::splat(2.0)).unwrap());
        let m = perturb(&nor, DVec3::new(0.6, 0.1, 0.0), n);
        assert!((m.dot(n) - 0.9912).abs() < 2e-4);
    }
}
