//! f_hex_x and f_hex_y (27, 28): coordinates in a honeycomb of the xy plane, fitted to
//! POV-Ray's printed values. The cells are centred on the lattice spanned by (√3, 0) and
//! (√3/2, 3/2) and measured with the hexagonal norm max(|dx|, |dx|/2 + √3/2 |dy|), whose
//! unit ball is a hexagon with vertices on ±y; z and the parameter have no effect.

use glam::{DVec2, DVec3};

const HALF_SQRT3: f64 = 0.866_025_403_784_438_6;

/// The lattice repeats every (√3, 3); within one such rectangle these centres suffice.
const CENTRES: [DVec2; 5] = [
    DVec2::new(0.0, 0.0),
    DVec2::new(2.0 * HALF_SQRT3, 0.0),
    DVec2::new(0.0, 3.0),
    DVec2::new(2.0 * HALF_SQRT3, 3.0),
    DVec2::new(HALF_SQRT3, 1.5),
];

/// |dx| and |dx|/2 + √3/2 |dy|: the first is the larger inside the hexagon's two sides
/// across x, the second in the four slanted sectors.
fn norms(d: DVec2) -> (f64, f64) {
    let d = d.abs();
    (d.x, d.x / 2.0 + HALF_SQRT3 * d.y)
}

/// The offset from the nearest cell centre.
fn offset(p: DVec3) -> DVec2 {
    let q = DVec2::new(p.x.rem_euclid(2.0 * HALF_SQRT3), p.y.rem_euclid(3.0));
    let mut best = q;
    let mut nearest = f64::INFINITY;
    for c in CENTRES {
        let (a, b) = norms(q - c);
        if a.max(b) < nearest {
            nearest = a.max(b);
            best = q - c;
        }
    }
    best
}

/// 27: the hexagonal distance from the nearest cell centre.
pub fn hex_x(p: DVec3) -> f64 {
    let (a, b) = norms(offset(p));
    a.max(b)
}

/// 28: the offset across that distance's direction: |dy| in the sectors facing ±x, the
/// component along the slanted side, |√3/2 |dx| - |dy|/2|, in the others.
pub fn hex_y(p: DVec3) -> f64 {
    let d = offset(p).abs();
    let (a, b) = norms(d);
    if a >= b {
        d.y
    } else {
        (HALF_SQRT3 * d.x - d.y / 2.0).abs()
    }
}
