//! POV-Ray's pattern functions. The closed forms were checked against povray renders of
//! each pattern on a plane (ambient 1, diffuse 0); the noise-based ones use penumbra's own
//! noise (noise.rs) and match POV-Ray in distribution only.

use std::f64::consts::{PI, TAU};

use glam::DVec3;

use super::noise::{dturbulence, lattice_hash, noise_with, turbulence};
use crate::scene::{Pattern, PatternKind, Quilted, Turbulence, Warp, Wave};

/// The ten wave sources of `ripples` and `waves` (unit vectors) and each source's wave
/// frequency for `waves`, measured from povray renders: first a least-squares fit of
/// `0.5 + 0.05 sum sin(2 pi |p - s|)` (ripples) and `0.5 + 0.02 sum sin(2 pi f |p - s|) / f`
/// (waves) to the patterns on nine planes (1.1e-4 RMS, 5 digits), then refined through the
/// normals' phases: a mirror under `ripples translate T scale F frequency F` shows each
/// source as a plane wave whose phase is F |T + s| (mod 1), fitted from POV-Ray's image at
/// F = 10^3, 10^4, 10^5 and 10^6 in turn (each fixing the next one's whole cycles), for T = 0
/// and half a unit along each axis; the distances give the components (and |s| = 1 to
/// 1e-8), `waves` at T = 0 gives f |s|. The three distances and the norm agree to 8e-8.
/// POV-Ray derives them from its noise tables, which penumbra does not have, so they are
/// kept as measured. The digits matter where a scene scales the pattern up and its
/// frequency by as much (textures/finishes/var_refl.pov: `scale 100000 frequency 100000`),
/// which multiplies the error in a source's distance into the wave's phase.
pub(crate) const WAVE_SOURCES: [([f64; 3], f64); 10] = [
    ([0.246190210, -0.914556759, -0.320899167], 0.991444768),
    ([-0.520489130, -0.386027152, -0.761625897], 0.400667436),
    ([-0.444551091, 0.623328980, 0.643300323], 0.433169652),
    ([0.564896733, 0.722040511, -0.399436075], 0.168513138),
    ([0.496586055, 0.668948173, 0.553091873], 0.709301133),
    ([0.137949445, -0.704642103, -0.696024039], 0.229672231),
    ([-0.552573186, -0.246075340, -0.796310200], 0.960041212),
    ([-0.666088953, -0.591878567, -0.453878056], 0.782972810),
    ([-0.064371810, -0.805951585, -0.588471174], 0.689189427),
    ([-0.604378218, 0.492048394, -0.626590240], 0.919115881),
];

/// The wrap POV-Ray uses after frequency and phase: slightly more than one, so that a
/// value of exactly 1 keeps the top entry of a colour map.
const WRAP: f64 = 1.00001;

/// Applies the warp chain (innermost last in the list is applied first to the point, so
/// later modifiers move what the earlier ones built) and the classic turbulence.
pub fn warp_point(pattern: &Pattern, p: DVec3) -> DVec3 {
    let turbulence = pattern
        .turbulence
        .as_ref()
        .filter(|_| !pattern.kind.handles_turbulence());
    warp_chain(&pattern.warps, turbulence, p)
}

/// A warp chain and classic turbulence on their own, for pigments without a pattern
/// (image maps). Classic turbulence comes last, in the innermost pattern space, wherever
/// it was written among the transforms (measured: POV-Ray's warp1.pov renders
/// `turbulence t rotate r` and `rotate r turbulence t` alike).
pub fn warp_chain(warps: &[Warp], turbulence: Option<&Turbulence>, mut p: DVec3) -> DVec3 {
    for w in warps.iter().rev() {
        p = match w {
            Warp::Transform(t) => t.inverse_point(p),
            Warp::Turbulence(t) => p + dturbulence(p, t) * t.amount,
            Warp::Repeat(r) => super::warps::repeat(r, p),
            Warp::BlackHole(b) => super::warps::black_hole(b, p),
            Warp::Mapping(m) => super::warps::mapping(m, p),
            Warp::Planar { orient, distance } => super::warps::planar(orient, *distance, p),
        };
    }
    if let Some(t) = turbulence {
        p += dturbulence(p, t) * t.amount;
    }
    p
}

/// The final pattern value in [0, 1] at a pattern-space point (before the pattern's own
/// warps), with frequency, phase and wave applied. List patterns give index / (n - 1).
pub fn pattern_value(pattern: &Pattern, p: DVec3) -> f64 {
    pattern_value_at(pattern, p, DVec3::ZERO)
}

/// As [`pattern_value`], where the surface's unit world normal is known (for `slope`;
/// without one, zero, slope reads as across its direction).
pub fn pattern_value_at(pattern: &Pattern, p: DVec3, normal: DVec3) -> f64 {
    let q = warp_point(pattern, p);
    if let PatternKind::Slope(slope) = &pattern.kind {
        return apply_wave(pattern, slope_value(slope, q, normal));
    }
    // A list pattern's value is the entry's index, unscaled: hexagon gives 0, 1 and 2
    // (measured with POV-Ray's `function { pattern { hexagon } }`), so its cells' edges
    // tilt a normal twice as far as 0, 0.5, 1 would (textures/patterns/hexagon.pov).
    if pattern.kind.list_size().is_some() {
        return list_index(&pattern.kind, q) as f64;
    }
    let raw = raw_value(pattern, q);
    apply_wave(pattern, raw)
}

/// Below this (2^50) a checker's three cell numbers are exact as integers and their sum
/// (below 2^52) is exact as a float, so both ways of finding its parity agree.
const CELLS_IN_INTEGERS: f64 = 1_125_899_906_842_624.0;

/// The entry a list pattern (checker, brick, hexagon) selects at a warped point.
pub fn list_index(kind: &PatternKind, p: DVec3) -> usize {
    match kind {
        PatternKind::Checker => {
            // POV-Ray nudges by 1e-10 so that faces at integer coordinates fall consistently.
            let q = (p + 1e-10).to_array();
            if q.iter().all(|v| v.abs() < CELLS_IN_INTEGERS) {
                // The cells' parity in integers: the library's floor and fmod (the baseline
                // target has no rounding instruction) were half a checker's pattern cost.
                let cell = |v: f64| {
                    let t = v as i64;
                    t - i64::from(t as f64 > v)
                };
                return ((cell(q[0]) + cell(q[1]) + cell(q[2])) & 1) as usize;
            }
            let s = q[0].floor() + q[1].floor() + q[2].floor();
            s.rem_euclid(2.0) as usize
        }
        PatternKind::Hexagon => hexagon(p),
        PatternKind::Square => square(p),
        PatternKind::Triangular => triangular(p),
        PatternKind::Brick { size, mortar } => brick(p, *size, *mortar),
        PatternKind::MaterialMap(m) => super::pigment::material_index(m, p),
        PatternKind::Object(o) => usize::from(o.holds(p)),
        _ => 0,
    }
}

/// Which list entry a pattern selects, for patterns used with a list of pigments.
pub fn pattern_index(pattern: &Pattern, p: DVec3) -> usize {
    list_index(&pattern.kind, warp_point(pattern, p))
}

fn apply_wave(pattern: &Pattern, raw: f64) -> f64 {
    let mut v = raw * pattern.frequency + pattern.phase;
    if !v.is_finite() {
        return 0.0;
    }
    // Patterns whose raw value lies in [0, 1] keep 1.0 at frequency 1 (WRAP > 1); negative
    // values come up by 1, not by WRAP (POV-Ray's printed values: gradient at x = -1.5
    // reads 0.50001, a fractal's real part -1.5261050 reads 0.4739050).
    // The remainder is v itself within the wrap, where a colour map's values mostly lie:
    // `%` calls a software fmod (60 instructions; pigment_pattern.pov -1.8% without it).
    if v.abs() >= WRAP {
        v %= WRAP;
    }
    if v < 0.0 {
        v += 1.0;
    }
    let v = v.clamp(0.0, 1.0);
    match pattern.wave {
        Wave::Ramp => v,
        Wave::Sine => 0.5 * (1.0 + (TAU * v).sin()),
        Wave::Triangle => {
            if v < 0.5 {
                2.0 * v
            } else {
                2.0 - 2.0 * v
            }
        }
        Wave::Scallop => (PI * v).sin().abs(),
        Wave::Cubic => v * v * (3.0 - 2.0 * v),
        Wave::Poly(e) => v.powf(e),
    }
}

/// The angle POV-Ray's spirals use: 0 on -y, increasing through +x, in [0, 2 pi).
fn spiral_angle(x: f64, y: f64, r: f64) -> f64 {
    if r == 0.0 {
        return 0.0;
    }
    let s = (y / r).clamp(-1.0, 1.0).asin();
    if x < 0.0 { 1.5 * PI - s } else { 0.5 * PI + s }
}

/// POV-Ray's gradient wraps values above 1 to [0, 1) itself, before the general wrap by
/// 1.00001 (measured on planes `gradient y` at y = 1.25, 2, 3: 0.25, 0, 0, where the
/// general wrap alone would give 0.24999, 0.99998, 0.99997); 1 itself stays 1, and negative
/// values are left to the general wrap (y = -0.5 reads 0.5, -1.5 reads 0.50001).
/// `slope`: see [`crate::scene::Slope`] for the rule and how it was measured. Values past
/// 1 wrap as gradient's do.
fn slope_value(slope: &crate::scene::Slope, p: DVec3, normal: DVec3) -> f64 {
    let ranged = |v: f64, (lo, hi): (f64, f64)| {
        if hi != lo { (v - lo) / (hi - lo) } else { v }
    };
    let cos = normal.dot(slope.direction).clamp(-1.0, 1.0);
    let s = ranged(0.5 + cos.asin() / PI, slope.range);
    let v = match slope.altitude {
        None => s,
        Some((a, weight, range)) => {
            let h = ranged(p.dot(a), range);
            let total = slope.weight + weight;
            if total > 0.0 {
                (slope.weight * s + weight * h) / total
            } else {
                s
            }
        }
    };
    gradient_value(v)
}

fn gradient_value(v: f64) -> f64 {
    if v > 1.0 { v - v.floor() } else { v }
}

/// The triangle wave of period 1 rising from 0 at integers to 1 at half-integers.
fn unit_triangle(v: f64) -> f64 {
    let f = v - v.floor();
    if f < 0.5 { 2.0 * f } else { 2.0 - 2.0 * f }
}

/// Granite and wrinkles hardly feel generator 1: povray's values under generator 1 are a
/// linear map of those under generator 2 (quantile residuals 0.002), nothing like bozo's
/// doubling. So they sum generator 2's noise and apply the measured map; under generator
/// 3 they sum generator 3's noise, and the map (gain, offset) fits povray's quantiles.
const GRANITE_GENERATOR1: (f64, f64) = (1.0168, 0.0011);
const GRANITE_GENERATOR3: (f64, f64) = (0.882, 0.046);
const WRINKLES_GENERATOR1: (f64, f64) = (1.0174, -0.0393);
const WRINKLES_GENERATOR3: (f64, f64) = (0.932, 0.023);

/// The noise the granite and wrinkles sums use under a generator (see above).
fn inner_generator(generator: u8) -> u8 {
    if generator == 3 { 3 } else { 2 }
}

fn raw_value(pattern: &Pattern, p: DVec3) -> f64 {
    match &pattern.kind {
        PatternKind::Gradient(g) => gradient_value(p.dot(*g)),
        PatternKind::Slope(slope) => slope_value(slope, p, DVec3::ZERO),
        PatternKind::MaterialMap(m) => super::pigment::material_index(m, p) as f64,
        PatternKind::Object(o) => f64::from(u8::from(o.holds(p))),
        PatternKind::BumpMap(_) => 0.0,
        // Measured: values above 1 wrap as gradient's do (1.25 and 10.25 read 0.25, 1 stays
        // 1), and -0.25 reads 0.75.
        PatternKind::Function(f) => gradient_value(f.at(p)),
        PatternKind::Onion => p.length(),
        PatternKind::Tiling(n) => super::tiling::tiling_value(*n, p),
        PatternKind::Pavement(v) => super::tiling::pavement_value(v, p),
        PatternKind::Radial => 0.25 + (p.x.atan2(p.z) + PI) / TAU,
        PatternKind::Leopard => {
            let s = (p.x.sin() + p.y.sin() + p.z.sin()) / 3.0;
            s * s
        }
        // POV-Ray truncates the arm count toward zero (3.5 arms draw 3, -3.5 draw -3).
        PatternKind::Spiral1(arms) => {
            let r = p.x.hypot(p.y);
            p.z + r + arms.trunc() * spiral_angle(p.x, p.y, r) / TAU
        }
        // The sum of two unit triangle waves (0 -> 1 -> 0 over a period of 1): one of
        // spiral1's argument, one of the radius alone. Measured against povray's own
        // function values to 3e-7 on thousands of points (arms 1, 2, 3, 5, -2, -3.5).
        PatternKind::Spiral2(arms) => {
            let r = p.x.hypot(p.y);
            let a = p.z + r + arms.trunc() * spiral_angle(p.x, p.y, r) / TAU;
            unit_triangle(a) + unit_triangle(r)
        }
        PatternKind::Marble => {
            p.x + classic(pattern).map_or(0.0, |t| t.amount.x * turbulence(p, &t))
        }
        PatternKind::Wood => wood(pattern, p),
        PatternKind::Agate { turbulence: scale } => {
            // The 1.3 gain on the turbulence and the 0.77 power match povray's agate.
            let t = classic(pattern).unwrap_or(Turbulence {
                amount: DVec3::ONE,
                ..Turbulence::default()
            });
            let arg = 1.3 * scale * turbulence(p, &t) + 1.1 * p.z;
            (0.5 * ((TAU * arg).sin() + 1.0)).clamp(0.0, 1.0).powf(0.77)
        }
        PatternKind::Bozo | PatternKind::Spotted | PatternKind::Bumps => {
            noise_with(p, pattern.noise_generator)
        }
        PatternKind::Dents => {
            let n = noise_with(p, pattern.noise_generator);
            n * n * n
        }
        PatternKind::Granite => granite(pattern, p),
        PatternKind::Wrinkles => wrinkles(pattern, p),
        PatternKind::Ripples => ripples(pattern, p),
        PatternKind::Waves => waves(pattern, p),
        PatternKind::Planar => 1.0 - p.y.abs().min(1.0),
        PatternKind::Spherical => 1.0 - p.length().min(1.0),
        PatternKind::Cylindrical => 1.0 - p.x.hypot(p.z).min(1.0),
        PatternKind::Boxed => 1.0 - p.abs().max_element().min(1.0),
        PatternKind::Crackle(c) => super::crackle::crackle_value(c, p, pattern.noise_generator),
        // Only a pigment_map reads `average`, and it averages its entries instead.
        PatternKind::Average => 0.0,
        PatternKind::DensityFile(grid) => voxel_value(grid, p),
        PatternKind::PigmentPattern(pig) => {
            let c = super::pigment::evaluate_pigment(pig, p);
            0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
        }
        PatternKind::Quilted(q) => quilted(q, p),
        PatternKind::Fractal(f) => super::fractal::fractal_value(f, p),
        PatternKind::Cells => cells(p),
        // Measured on a 2 x 2 image: red, green, blue read 0.2971, 0.5889, 0.1140; alpha
        // 255, 128, 0 read 0, 0.498, 1 under use_alpha.
        PatternKind::ImagePattern { image, use_alpha } => {
            let c = super::pigment::image_colour(image, p);
            if *use_alpha {
                c.transmit
            } else {
                0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z
            }
        }
        PatternKind::Checker
        | PatternKind::Hexagon
        | PatternKind::Square
        | PatternKind::Triangular
        | PatternKind::Brick { .. } => list_index(&pattern.kind, p) as f64,
    }
}

/// quilted's normalisation: 1 / (sqrt 3 / 2), the distance from a cube's centre to its
/// corners (measured: the value is this times the mean below, 0.0962250449 = 1 / (6 sqrt 3)
/// halfway along an axis with both controls 0.5; the normal's gain is the same).
pub(crate) const QUILT_SCALE: f64 = 1.154_700_538_379_251_5;

/// The cubic Bezier from 0 to 1 with inner control points c0 and c1, at t.
fn quilt_cubic(t: f64, c0: f64, c1: f64) -> f64 {
    let it = 1.0 - t;
    t * t * t + 3.0 * t * it * it * c0 + 3.0 * t * t * it * c1
}

/// The offset of `p` from the centre of its unit cube, scaled by the Bezier of its length:
/// the bulge that both the quilted value and its own normal are made of.
pub(crate) fn quilt_vector(q: &Quilted, p: DVec3) -> DVec3 {
    let v = p - p.floor() - DVec3::splat(0.5);
    v * quilt_cubic(v.length(), q.control0, q.control1)
}

/// `quilted`: the mean of the bulge's |components|, scaled (measured against POV-Ray's
/// printed values to 1e-9 for controls (0, 0), (0, 1), (1, 0), (0.5, 0.5), (1, 1)).
fn quilted(q: &Quilted, p: DVec3) -> f64 {
    QUILT_SCALE * quilt_vector(q, p).abs().element_sum() / 3.0
}

const CELLS_SEED: u32 = 0x3c6e_f372;

/// `cells`: a uniform random value in [0, 1) per unit cube, constant inside it (POV-Ray's
/// values are its own hash's; measured over 3000 cubes: uniform, mean 0.506, sd 0.2886).
fn cells(p: DVec3) -> f64 {
    if !p.is_finite() {
        return 0.0;
    }
    let c = p.floor();
    let h = lattice_hash(c.x as i64, c.y as i64, c.z as i64, CELLS_SEED);
    f64::from(h) / (f64::from(u32::MAX) + 1.0)
}

fn wood(pattern: &Pattern, p: DVec3) -> f64 {
    // With turbulence, POV-Ray bends the rings by a sine of the turbulent
    // coordinate (amplitude 1, frequency = the turbulence amount); a plain
    // displacement gives a third of povray's spectral power at high frequencies.
    let (x, y) = match classic(pattern) {
        Some(t) => {
            let d = dturbulence(p, &t);
            (
                p.x + (TAU * (p.x + d.x) * t.amount.x).sin(),
                p.y + (TAU * (p.y + d.y) * t.amount.y).sin(),
            )
        }
        None => (p.x, p.y),
    };
    x.hypot(y)
}

fn granite(pattern: &Pattern, p: DVec3) -> f64 {
    // Six octaves of |0.5 - noise| at 4x frequency; the gain 2 is fitted to
    // povray's granite quantiles.
    let inner = inner_generator(pattern.noise_generator);
    let mut sum = 0.0;
    let mut freq = 1.0;
    for _ in 0..6 {
        sum += (0.5 - noise_with(4.0 * p * freq, inner)).abs() / freq;
        freq *= 2.0;
    }
    let (gain, offset) = match pattern.noise_generator {
        1 => GRANITE_GENERATOR1,
        3 => GRANITE_GENERATOR3,
        _ => (1.0, 0.0),
    };
    (gain * 2.0 * sum + offset).max(0.0)
}

fn wrinkles(pattern: &Pattern, p: DVec3) -> f64 {
    // Ten octaves of noise around 0.5, weights halving: povray's wrinkles is
    // centred on 0.5 and 15% wider than bozo, which this sum reproduces.
    let inner = inner_generator(pattern.noise_generator);
    let mut sum = 0.5;
    let mut f = 1.0;
    for _ in 0..10 {
        sum += (noise_with(p * f, inner) - 0.5) / f;
        f *= 2.0;
    }
    let (gain, offset) = match pattern.noise_generator {
        1 => WRINKLES_GENERATOR1,
        3 => WRINKLES_GENERATOR3,
        _ => (1.0, 0.0),
    };
    (gain * sum + offset).clamp(0.0, 1.0)
}

/// Ten wave sources at POV-Ray's measured positions, each a sine of the distance.
fn ripples(pattern: &Pattern, p: DVec3) -> f64 {
    let mut sum = 0.0;
    for (s, _) in WAVE_SOURCES {
        let d = p.distance(DVec3::from(s));
        sum += (TAU * (d * pattern.frequency + pattern.phase)).sin();
    }
    0.5 + 0.5 * sum / WAVE_SOURCES.len() as f64
}

/// As ripples, with each source's own frequency, its amplitude falling with it.
fn waves(pattern: &Pattern, p: DVec3) -> f64 {
    let mut sum = 0.0;
    for (s, f) in WAVE_SOURCES {
        let d = p.distance(DVec3::from(s));
        sum += (TAU * (d * f * pattern.frequency + pattern.phase)).sin() / f;
    }
    0.5 + 0.2 * sum / WAVE_SOURCES.len() as f64
}

/// Marble, wood and agate read the classic turbulence (when given) themselves.
fn classic(pattern: &Pattern) -> Option<Turbulence> {
    pattern.turbulence
}

/// Hexagons in the x-z plane with circumradius 1 and vertices on the x axis; the hexagon
/// around the origin is entry 0 and the three colours alternate so no neighbours match.
fn hexagon(p: DVec3) -> usize {
    // Axial coordinates: centres at a*(1.5, sqrt3/2) + b*(0, sqrt3).
    let s3 = 3f64.sqrt();
    let q = p.x / 1.5;
    let r = p.z / s3 - q / 2.0;
    let s = -q - r;
    let (mut rq, mut rr, rs) = (q.round(), r.round(), s.round());
    let (dq, dr, ds) = ((rq - q).abs(), (rr - r).abs(), (rs - s).abs());
    if dq > dr && dq > ds {
        rq = -rr - rs;
    } else if dr > ds {
        rr = -rq - rs;
    }
    let c = (rr - rq).rem_euclid(3.0);
    if c.is_finite() { c as usize % 3 } else { 0 }
}

/// Unit squares in the x-z plane. Measured with POV-Ray 3.7 from above: the square at
/// (0, 0) takes entry 0, (0, 1) entry 1, (1, 1) entry 2 and (1, 0) entry 3, repeating
/// every two units.
fn square(p: DVec3) -> usize {
    if !p.is_finite() {
        return 0;
    }
    let odd = |v: f64| v.floor().rem_euclid(2.0) == 1.0;
    match (odd(p.x), odd(p.z)) {
        (false, false) => 0,
        (false, true) => 1,
        (true, true) => 2,
        (true, false) => 3,
    }
}

/// Equilateral triangles of side 1 in the x-z plane, one vertex at the origin and edges
/// along x: the six around the origin take entries 0 to 5 going from +x towards +z.
/// Measured with POV-Ray 3.7 from above: in lattice coordinates (u, v) with x = u + v / 2,
/// z = v sqrt(3) / 2, the triangle in cell (i, j) below its diagonal takes entry 0, 4, 2
/// and the one above it 3, 5, 1 as (i + 2 j) mod 3 is 0, 1, 2.
fn triangular(p: DVec3) -> usize {
    if !p.is_finite() {
        return 0;
    }
    let v = p.z * 2.0 / 3f64.sqrt();
    let u = p.x - v / 2.0;
    let (i, j) = (u.floor(), v.floor());
    let above = (u - i) + (v - j) > 1.0;
    let m = (i + 2.0 * j).rem_euclid(3.0) as usize % 3;
    if above { [3, 5, 1][m] } else { [0, 4, 2][m] }
}

/// Bricks of `size` with mortar of width `mortar` at the high end of each brick along
/// each axis; odd rows (in y) are shifted half a brick in x, even rows in z.
fn brick(p: DVec3, size: DVec3, mortar: f64) -> usize {
    if size.min_element() <= 0.0 || !p.is_finite() {
        return 0;
    }
    // A nudge like checker's: a floor at y = 0 must not flicker between the top of one
    // row's mortar and the bottom of the next row with the hit point's rounding.
    let p = p + DVec3::splat(1e-6);
    let row = (p.y / size.y).floor();
    let odd = row.rem_euclid(2.0) == 1.0;
    let y = p.y - row * size.y;
    let x = (p.x - if odd { size.x / 2.0 } else { 0.0 }).rem_euclid(size.x);
    let z = (p.z - if odd { 0.0 } else { size.z / 2.0 }).rem_euclid(size.z);
    if y >= size.y - mortar || x >= size.x - mortar || z >= size.z - mortar {
        0
    } else {
        1
    }
}

/// A df3 grid over the unit cube, 0 outside it. Measured on povray 3.7 with 2- and 4-voxel
/// files: without interpolation voxel k covers [k / n, (k + 1) / n); with `interpolate 1`
/// voxel k sits at k / n and the value between voxels is linear, wrapping from the last
/// voxel back to the first (a file [1, 0] rises back to 1 at x = 1).
fn voxel_value(grid: &crate::scene::VoxelGrid, p: DVec3) -> f64 {
    let q = p.to_array();
    if q.iter().any(|&c| !(0.0..1.0).contains(&c)) {
        return 0.0;
    }
    let [nx, ny, nz] = grid.size;
    let at = |i: usize, j: usize, k: usize| f64::from(grid.values[i + nx * (j + ny * k)]);
    let u = [q[0] * nx as f64, q[1] * ny as f64, q[2] * nz as f64];
    let cell = |c: f64, n: usize| (c.floor() as usize).min(n - 1);
    let (i, j, k) = (cell(u[0], nx), cell(u[1], ny), cell(u[2], nz));
    if !grid.trilinear {
        return at(i, j, k);
    }
    let t = [u[0].fract(), u[1].fract(), u[2].fract()];
    let (i1, j1, k1) = ((i + 1) % nx, (j + 1) % ny, (k + 1) % nz);
    let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
    let plane = |k: usize| {
        lerp(
            lerp(at(i, j, k), at(i1, j, k), t[0]),
            lerp(at(i, j1, k), at(i1, j1, k), t[0]),
            t[1],
        )
    };
    lerp(plane(k), plane(k1), t[2])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(size: [usize; 3], values: &[f32], trilinear: bool) -> crate::scene::VoxelGrid {
        crate::scene::VoxelGrid {
            size,
            values: values.to_vec(),
            trilinear,
        }
    }

    #[test]
    fn df3_voxels_as_povray_reads_them() {
        // povray 3.7, a 4 x 1 x 1 file [0, 85, 170, 255] seen through emitting media.
        let g = grid([4, 1, 1], &[0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0], false);
        let at = |g: &crate::scene::VoxelGrid, x: f64| voxel_value(g, DVec3::new(x, 0.5, 0.5));
        assert!((at(&g, 0.3) - 1.0 / 3.0).abs() < 1e-6);
        assert_eq!(at(&g, 0.99), 1.0);
        assert_eq!(at(&g, 1.0), 0.0);
        assert_eq!(at(&g, -0.01), 0.0);
        let g = grid([4, 1, 1], &[0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0], true);
        // 0.138 -> 0.183 and 0.812 -> 0.750 in povray's image.
        assert!((at(&g, 0.1375) - 0.1833).abs() < 1e-3);
        assert!((at(&g, 0.8125) - 0.75).abs() < 1e-3);
        // [1, 0] wraps back up towards the first voxel: 0.962 -> 0.925.
        let w = grid([2, 1, 1], &[1.0, 0.0], true);
        assert!((at(&w, 0.9625) - 0.925).abs() < 1e-3);
    }

    /// The checker's integer parity gives the floating-point formula's cell at integers,
    /// beside them, far out and past the integer range (which takes the formula itself).
    #[test]
    fn checker_cells_in_integers_match_the_floor_formula() {
        let formula = |p: DVec3| {
            let s = (p.x + 1e-10).floor() + (p.y + 1e-10).floor() + (p.z + 1e-10).floor();
            s.rem_euclid(2.0) as usize
        };
        let mut uniform = crate::geometry::uniform_stream(0x2545_F491_4F6C_DD1Du64);
        for scale in [1.0, 3.0, 1e6, 1e14, 1.1e15, 1.2e15, 1e18, 1e300] {
            for _ in 0..2000 {
                let mut v = || {
                    let x = (uniform() * 2.0 - 1.0) * scale;
                    // A third of the coordinates on an integer or just below one.
                    match (uniform() * 3.0) as u32 {
                        0 => x.round(),
                        1 => x.round() - 1e-10,
                        _ => x,
                    }
                };
                let p = DVec3::new(v(), v(), v());
                assert_eq!(list_index(&PatternKind::Checker, p), formula(p), "at {p}");
            }
        }
    }

    fn value(kind: PatternKind, p: DVec3) -> f64 {
        pattern_value(&Pattern::new(kind), p)
    }

    #[test]
    fn closed_forms_match_povray_probes() {
        // Values read back from povray renders of the plain patterns.
        let g = value(PatternKind::Gradient(DVec3::X), DVec3::new(-1.25, 0.0, 0.0));
        assert!((g - 0.75).abs() < 1e-4);
        let m = value(PatternKind::Marble, DVec3::new(-1.75, 0.0, 0.0));
        assert!((m - 0.5).abs() < 1e-4);
        // spiral1 2 at (1.031, -1.031, 0) read 0.583; at (-0.719, -0.781, 0) read 0.35.
        let s = value(PatternKind::Spiral1(2.0), DVec3::new(1.031, -1.031, 0.0));
        assert!((s - 0.583).abs() < 0.01, "{s}");
        let s = value(PatternKind::Spiral1(2.0), DVec3::new(-0.719, -0.781, 0.0));
        assert!((s - 0.35).abs() < 0.01, "{s}");
    }

    #[test]
    fn spiral2_matches_povray_function_values() {
        // (arms, x, y, z, ramp_wave value, default (triangle) value) read from povray's
        // `function { pattern { spiral2 ARMS ramp_wave } }` and the same without a wave.
        let probes = [
            (1.0, -1.76032359, -0.32739320, -0.32383302, 0.91086596),
            (1.0, 0.07218280, -1.05077923, 1.58034158, 0.81748498),
            (1.0, 0.31565669, -0.01475509, -0.51548382, 0.71816950),
            (1.0, 0.33530032, 2.05152706, 1.38869078, 0.27418686),
            (1.0, -1.29024387, 0.36725182, -0.70713462, 0.36342372),
            (1.0, -0.23117723, -0.55826645, 1.19703998, 0.31392417),
            (5.0, -0.44890984, -0.14205427, 0.79361164, 0.45837877),
            (5.0, -1.96470031, -0.30245123, 0.66584444, 0.97383583),
            (5.0, -0.02157199, 0.00336439, 0.41031004, 0.16171497),
            (5.0, -1.46620541, 0.46715157, 0.28254284, 0.57417190),
            (5.0, -0.49750781, 0.24783762, 0.15477564, 0.07396990),
            // 5.7 arms draw 5.
            (5.7, -0.49750781, 0.24783762, 0.15477564, 0.07396990),
        ];
        for (arms, x, y, z, ramp) in probes {
            let mut pat = Pattern::new(PatternKind::Spiral2(arms));
            let p = DVec3::new(x, y, z);
            pat.wave = Wave::Ramp;
            let r = pattern_value(&pat, p);
            assert!((r - ramp).abs() < 1e-5, "arms {arms} at {p}: {r} vs {ramp}");
            // The default wave is the triangle of the ramp value.
            let t = value(PatternKind::Spiral2(arms), p);
            let want = if ramp < 0.5 {
                2.0 * ramp
            } else {
                2.0 - 2.0 * ramp
            };
            assert!((t - want).abs() < 1e-5, "arms {arms} at {p}: {t} vs {want}");
        }
    }

    #[test]
    fn square_and_triangular_layout() {
        let s = |x, z| square(DVec3::new(x, 0.0, z));
        assert_eq!(
            [s(0.5, 0.5), s(0.5, 1.5), s(1.5, 1.5), s(1.5, 0.5)],
            [0, 1, 2, 3]
        );
        assert_eq!(s(-0.5, -0.5), 2);
        let t = |x: f64, z: f64| triangular(DVec3::new(x, 0.0, z));
        // Centroids of the triangles with a corner at the origin, going round it from +x
        // towards +z: POV-Ray's entries there (read from its render).
        let centroid = |deg: f64| {
            let a = deg.to_radians();
            t(a.cos() / 3f64.sqrt(), a.sin() / 3f64.sqrt())
        };
        assert_eq!(
            [30.0, 90.0, 150.0, 210.0, 270.0, 330.0].map(centroid),
            [0, 1, 2, 3, 4, 5]
        );
    }

    #[test]
    fn hexagon_and_brick_layout() {
        let h = |x, z| hexagon(DVec3::new(x, 0.0, z));
        assert_eq!(h(0.0, 0.0), 0);
        assert_eq!(h(0.0, 1.732), 1);
        assert_eq!(h(1.5, 0.866), 2);
        assert_eq!(h(1.5, -0.866), 1);
        assert_eq!(h(-1.5, 0.866), 2);
        let b = |x, y, z| brick(DVec3::new(x, y, z), DVec3::new(8.0, 3.0, 4.5), 0.5);
        assert_eq!(b(-0.25, 1.5, 0.0), 0);
        assert_eq!(b(0.25, 1.5, 0.0), 1);
        assert_eq!(b(2.0, 1.5, 2.0), 0);
        assert_eq!(b(2.0, -1.5, -0.25), 0);
        assert_eq!(b(2.0, 2.75, 1.0), 0);
        assert_eq!(b(0.0, f64::NAN, 0.0), 0);
    }

    #[test]
    fn gradient_wraps_like_povray_at_integers() {
        // povray's values on planes `gradient y` at these heights (16-bit linear output).
        let p = Pattern::new(PatternKind::Gradient(DVec3::Y));
        let at = |y: f64| pattern_value(&p, DVec3::new(0.0, y, 0.0));
        for (y, want) in [
            (1.25, 0.25),
            (2.0, 0.0),
            (3.0, 0.0),
            (1.0, 1.0),
            (0.25, 0.25),
        ] {
            assert!((at(y) - want).abs() < 1e-9, "y = {y}: {}", at(y));
        }
        // POV-Ray's printed `function { pattern { gradient y } }` values below 0.
        for (y, want) in [(-0.5, 0.5), (-0.25, 0.75), (-1.5, 0.50001), (-2.0, 0.00001)] {
            assert!((at(y) - want).abs() < 1e-6, "y = {y}: {}", at(y));
        }
    }

    #[test]
    fn waves_by_hand() {
        let mut p = Pattern::new(PatternKind::Gradient(DVec3::X));
        p.wave = Wave::Sine;
        assert!((pattern_value(&p, DVec3::new(0.25, 0.0, 0.0)) - 1.0).abs() < 1e-9);
        p.wave = Wave::Cubic;
        assert!((pattern_value(&p, DVec3::new(0.5, 0.0, 0.0)) - 0.5).abs() < 1e-9);
        p.wave = Wave::Ramp;
        p.frequency = 2.0;
        p.phase = 0.1;
        assert!((pattern_value(&p, DVec3::new(0.3, 0.0, 0.0)) - 0.7).abs() < 1e-9);
        assert!((pattern_value(&p, DVec3::new(-0.3, 0.0, 0.0)) - 0.5).abs() < 1e-4);
    }

    #[test]
    fn quilted_matches_povray_printed_values() {
        // (control0, control1, x, y, z, value) from POV-Ray's `#debug` of `function {
        // pattern { quilted control0 C0 control1 C1 } }`.
        let probes = [
            (0.5, 0.5, 0.1, 0.2, 0.3, 0.183_231_750),
            (0.5, 0.5, 0.5, 0.5, 0.5, 0.0),
            (0.5, 0.5, 0.25, 0.75, 0.1, 0.182_014_026),
            (0.5, 0.5, 1.3, -0.2, 2.7, 0.116_813_759),
            (0.5, 0.5, 0.0, 0.5, 0.5, 0.096_225_045),
            (0.5, 0.5, 0.0, 0.0, 0.5, 0.255_655_919),
            (0.0, 0.0, 0.05, 0.5, 0.5, 0.015_783_313),
            (1.0, 1.0, 0.1, 0.5, 0.5, 0.120_704_696),
            (1.0, 0.0, 0.2, 0.5, 0.5, 0.054_039_985),
            (0.0, 1.0, 0.3, 0.5, 0.5, 0.008_005_924),
        ];
        for (control0, control1, x, y, z, want) in probes {
            let q = Quilted { control0, control1 };
            let v = value(PatternKind::Quilted(q), DVec3::new(x, y, z));
            assert!(
                (v - want).abs() < 1e-8,
                "{q:?} at ({x}, {y}, {z}): {v} vs {want}"
            );
        }
        // The default controls are 1 and 1.
        let d = value(
            PatternKind::Quilted(Quilted::default()),
            DVec3::new(0.1, 0.2, 0.3),
        );
        assert!((d - 0.312_364_701).abs() < 1e-8, "{d}");
    }

    #[test]
    fn cells_are_constant_per_unit_cube() {
        let mut seen = Vec::new();
        for i in -20..20 {
            let corner = DVec3::new(f64::from(i) * 1.7, f64::from(i % 7), -f64::from(i)).floor();
            let v = value(PatternKind::Cells, corner + DVec3::splat(0.5));
            assert!((0.0..1.0).contains(&v));
            for d in [
                DVec3::ZERO,
                DVec3::new(0.999, 0.3, 0.7),
                DVec3::new(0.2, 0.999, 0.001),
            ] {
                assert_eq!(value(PatternKind::Cells, corner + d), v);
            }
            seen.push(v);
        }
        // Neighbouring cubes differ and the values spread over [0, 1) (POV-Ray: uniform).
        let mean = seen.iter().sum::<f64>() / seen.len() as f64;
        assert!((mean - 0.5).abs() < 0.15, "{mean}");
        let a = value(PatternKind::Cells, DVec3::new(-0.0001, 0.0, 0.0));
        assert_ne!(a, value(PatternKind::Cells, DVec3::ZERO));
    }

    #[test]
    fn ripples_and_waves_match_povray_probes() {
        // povray pigment values on the plane z = 0.5 (half-float renders).
        for (kind, x, y, want) in [
            (PatternKind::Ripples, -3.125, 2.291_666_7, 0.4526),
            (PatternKind::Ripples, 0.208_333_3, -1.875, 0.375),
            (PatternKind::Waves, -3.125, 2.291_666_7, 0.3938),
            (PatternKind::Waves, 0.208_333_3, -1.875, 0.6006),
        ] {
            let v = value(kind.clone(), DVec3::new(x, y, 0.5));
            assert!((v - want).abs() < 1e-3, "{kind:?} {v}");
        }
    }
}
