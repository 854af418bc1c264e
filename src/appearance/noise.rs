//! penumbra's own gradient noise. POV-Ray's noise comes from private tables that are its
//! code, so penumbra hashes lattice points instead, and scales the result so that the
//! value distribution matches POV-Ray's default generator (noise_generator 2) as measured
//! from povray renders (docs/noise.md). Lattice spacing is one unit, as in POV-Ray, so the
//! spectra agree too.

use glam::DVec3;

use crate::scene::Turbulence;

/// Maps the raw value-gradient noise to POV-Ray's [0, 1] value around 0.5. Fitted to the
/// 5%..95% quantile width of povray's `bozo` over four 32 x 32 unit slices.
const NOISE_SCALE: f64 = 0.48;
/// The vector noise's lattice: slightly stretched, which matched povray's turbulence
/// warps (spectra within 10%).
const LATTICE: f64 = 0.95;
/// Weight of the per-corner random value beside the random gradient. Pure gradient noise
/// has too little power above 2 cycles per unit and too much at 0.5-2 (by 20-30%);
/// half a random value per corner brings every octave band within about 5% of povray's.
const VALUE_WEIGHT: f64 = 0.5;
/// The spread of the vector noise, fitted to povray's turbulence warp displacements.
const DNOISE_SCALE: f64 = 1.0;

/// A 32-bit integer hash (lowbias32 by Chris Wellons), good enough to pick gradients.
#[inline]
pub(crate) fn hash(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    x
}

#[inline]
pub(crate) fn lattice_hash(i: i64, j: i64, k: i64, seed: u32) -> u32 {
    let h = hash((i as u32) ^ seed);
    let h = hash(h ^ (j as u32).wrapping_mul(0x9e37_79b9));
    hash(h ^ (k as u32).wrapping_mul(0x85eb_ca6b))
}

/// What one step along each axis adds to a corner's 64-bit linear form (odd constants with
/// well-mixed bits: the golden ratio's and two of xxHash's primes).
const LATTICE_STEP: [u64; 3] = [
    0x9e37_79b9_7f4a_7c15,
    0xc2b2_ae3d_27d4_eb4f,
    0x1656_67b1_9e37_79f9,
];

/// A hash per corner of the cell at (i, j, k) under `seed` (corner `dx | dy << 1 | dz << 2`):
/// the corner's linear form in 64 bits, folded to 32 and hashed once. The forms of a cell's
/// corners are the cell's plus a constant each (additions, no multiplication per corner),
/// and one 32-bit hash per corner is what the compiler runs four lanes at a time; the
/// lattice hash that `cells` and `crackle` use chains three hashes per point, and here it
/// took a third of a cloudy sky's render. Neighbouring corners' forms differ by large odd
/// constants, so their hashes are independent as far as the noise's statistics can show
/// (tests/appearance_noise.rs compares them with POV-Ray's).
#[inline]
fn corner_hashes(i: i64, j: i64, k: i64, seed: u32) -> [u32; 8] {
    let [a, b, c] = LATTICE_STEP;
    let base = (i as u64)
        .wrapping_mul(a)
        .wrapping_add((j as u64).wrapping_mul(b))
        .wrapping_add((k as u64).wrapping_mul(c));
    let offsets = [
        0,
        a,
        b,
        a.wrapping_add(b),
        c,
        a.wrapping_add(c),
        b.wrapping_add(c),
        a.wrapping_add(b).wrapping_add(c),
    ];
    let folded: [u32; 8] = std::array::from_fn(|corner| {
        let form = base.wrapping_add(offsets[corner]);
        (form ^ (form >> 32)) as u32
    });
    folded.map(|f| hash(f ^ seed))
}

/// The twelve cube-edge directions plus four repeats, as in improved Perlin noise: no
/// axis-aligned gradients, so the noise has no visible grid at its zero crossings. Per
/// code, the gradient's components (one of them 0): read from a table, where a `match` on
/// a random hash was a branch mispredicted about half the time at every corner.
const GRADIENTS: [[f64; 3]; 16] = [
    [1.0, 1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, -1.0, 0.0],
    [1.0, 0.0, 1.0],
    [-1.0, 0.0, 1.0],
    [1.0, 0.0, -1.0],
    [-1.0, 0.0, -1.0],
    [0.0, 1.0, 1.0],
    [0.0, -1.0, 1.0],
    [0.0, 1.0, -1.0],
    [0.0, -1.0, -1.0],
    [1.0, 1.0, 0.0],
    [0.0, -1.0, 1.0],
    [-1.0, 1.0, 0.0],
    [0.0, -1.0, -1.0],
];

/// The gradient of code `h` dotted with `d`: `x + y`, `-x + y`, `x - y` ... to the last
/// bit, as a sign times a coordinate is exact and the zero component's product (a zero,
/// as no coordinate of a corner's offset is -0) leaves the sum as it was.
#[inline]
fn grad(h: u32, d: [f64; 3]) -> f64 {
    let g = GRADIENTS[(h & 15) as usize];
    g[0] * d[0] + g[1] * d[1] + g[2] * d[2]
}

/// The cubic s-curve: POV-Ray's noise is smoother than improved Perlin noise's quintic
/// curve gives (the quintic puts 3x too much power at 1-2 cycles per unit).
#[inline]
fn fade(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

#[inline]
fn lerp(t: f64, a: f64, b: f64) -> f64 {
    a + t * (b - a)
}

/// The lattice cell around a point, its offset in it and the s-curve of the offset: what
/// noises with different seeds at one point share.
struct LatticeCell {
    corner: (i64, i64, i64),
    f: DVec3,
    fade: DVec3,
}

impl LatticeCell {
    /// `None` for a point with a coordinate that is not finite (its noise is 0).
    #[inline]
    fn of(p: DVec3) -> Option<LatticeCell> {
        if !p.is_finite() {
            return None;
        }
        let fl = p.floor();
        let f = p - fl;
        Some(LatticeCell {
            corner: (fl.x as i64, fl.y as i64, fl.z as i64),
            f,
            fade: DVec3::new(fade(f.x), fade(f.y), fade(f.z)),
        })
    }

    /// Its corners' hashes under `seed` ([`corner_hashes`]).
    #[inline]
    fn hashes(&self, seed: u32) -> [u32; 8] {
        let (i, j, k) = self.corner;
        corner_hashes(i, j, k, seed)
    }

    /// Gradient noise under `seed`.
    #[inline]
    fn gradient(&self, seed: u32) -> f64 {
        self.gradient_of(&self.hashes(seed), 0)
    }

    /// Three independent gradient noises, one from each 4-bit field of the corners' hashes
    /// (the low 12 bits): a vector noise at the cost of one set of hashes.
    #[inline]
    fn gradients(&self, seed: u32) -> DVec3 {
        let hashes = self.hashes(seed);
        DVec3::new(
            self.gradient_of(&hashes, 0),
            self.gradient_of(&hashes, 4),
            self.gradient_of(&hashes, 8),
        )
    }

    /// Gradient noise with each corner's code in bits `shift..shift + 4` of its hash.
    #[inline]
    fn gradient_of(&self, hashes: &[u32; 8], shift: u32) -> f64 {
        let (f, (u, v, w)) = (self.f, (self.fade.x, self.fade.y, self.fade.z));
        let g = |di: usize, dj: usize, dk: usize| {
            grad(
                hashes[di | dj << 1 | dk << 2] >> shift,
                [f.x - di as f64, f.y - dj as f64, f.z - dk as f64],
            )
        };
        lerp(
            w,
            lerp(
                v,
                lerp(u, g(0, 0, 0), g(1, 0, 0)),
                lerp(u, g(0, 1, 0), g(1, 1, 0)),
            ),
            lerp(
                v,
                lerp(u, g(0, 0, 1), g(1, 0, 1)),
                lerp(u, g(0, 1, 1), g(1, 1, 1)),
            ),
        )
    }

    /// Value-gradient noise under `seed`: each corner's value and gradient components are
    /// the four 16-bit halves of its hash and of one more hash of it. Computed as arrays
    /// over the eight corners, each element with the same operations in the same order as
    /// corner by corner, so that the compiler vectorises the hashes, the conversions and
    /// the products; the sum stays in corner order.
    #[inline]
    fn value_gradient(&self, seed: u32) -> f64 {
        let hashes = self.hashes(seed);
        let more = hashes.map(|h| hash(h ^ 0x68e3_1da4));
        let (value, gx) = (hashes.map(low_unit), hashes.map(|h| low_unit(h >> 16)));
        let (gy, gz) = (more.map(low_unit), more.map(|h| low_unit(h >> 16)));
        // Per corner (dx | dy << 1 | dz << 2): its offset and weight along each axis.
        let along = |f: f64, fade: f64, bit: usize| {
            let (d, w) = ([f, f - 1.0], [1.0 - fade, fade]);
            (
                std::array::from_fn::<f64, 8, _>(|c| d[c >> bit & 1]),
                std::array::from_fn::<f64, 8, _>(|c| w[c >> bit & 1]),
            )
        };
        let (dx, wx) = along(self.f.x, self.fade.x, 0);
        let (dy, wy) = along(self.f.y, self.fade.y, 1);
        let (dz, wz) = along(self.f.z, self.fade.z, 2);
        let mut term = [0.0; 8];
        for c in 0..8 {
            let v = VALUE_WEIGHT * value[c] + gx[c] * dx[c] + gy[c] * dy[c] + gz[c] * dz[c];
            term[c] = wx[c] * wy[c] * wz[c] * v;
        }
        term.iter().fold(0.0, |sum, t| sum + t)
    }
}

/// Gradient noise in about [-1, 1], zero on lattice points.
pub fn gradient_noise(p: DVec3, seed: u32) -> f64 {
    LatticeCell::of(p).map_or(0.0, |c| c.gradient(seed))
}

/// A uniform value in [-1, 1] from the low 16 bits of a hash: 65,536 levels, finer than
/// any statistic of the noise can tell from a continuous uniform value.
#[inline]
fn low_unit(h: u32) -> f64 {
    f64::from(h & 0xffff) * (2.0 / 65_535.0) - 1.0
}

/// Value-gradient noise: each lattice corner carries a random value and a random gradient
/// (components uniform in [-1, 1]), blended with the cubic s-curve.
pub fn value_gradient_noise(p: DVec3) -> f64 {
    value_gradient_noise_seeded(p, 0x5eed_0001)
}

/// Three independent value-gradient noises: the vector that perturbs `bumps`, `dents` and
/// `wrinkles` normals. With the scalar noise's construction, each component has the
/// spectrum of POV-Ray's noise, as POV-Ray's vector noise does (docs/appearance.md).
pub fn value_gradient_vector(p: DVec3) -> DVec3 {
    let Some(cell) = LatticeCell::of(p) else {
        return DVec3::ZERO;
    };
    DVec3::new(
        cell.value_gradient(0x0bad_5eed),
        cell.value_gradient(0x1dea_5eed),
        cell.value_gradient(0x2fab_5eed),
    )
}

fn value_gradient_noise_seeded(p: DVec3, seed: u32) -> f64 {
    LatticeCell::of(p).map_or(0.0, |c| c.value_gradient(seed))
}

/// POV-Ray's `Noise`: a value in [0, 1] around 0.5.
pub fn noise(p: DVec3) -> f64 {
    (0.5 + NOISE_SCALE * value_gradient_noise(p)).clamp(0.0, 1.0)
}

/// povray's generator 1 is generator 2 without its range correction: over the same
/// points (same tables) bozo's quantiles satisfy n1 = 2.0414 n2 - 0.5524 to within 4e-5,
/// so generator 1 is twice as wide, with 5% of its values below 0.066.
const GENERATOR1: (f64, f64) = (2.0414, -0.5524);
/// Generator 3 (povray's improved Perlin noise) behaves as gradient noise over the twelve
/// cube-edge gradients with the cubic s-curve: that construction's octave-band powers lie
/// within 2% of povray's bozo, while the quintic curve of Perlin's paper puts 1.8x
/// povray's power at 1-2 cycles per unit. The gain is fitted to bozo's quantiles.
const GENERATOR3_SCALE: f64 = 0.5617;
const GENERATOR3_SEED: u32 = 0x5eed_0003;

/// POV-Ray's `Noise` under `noise_generator` 1, 2 (the default) or 3, in [0, 1].
pub fn noise_with(p: DVec3, generator: u8) -> f64 {
    match generator {
        1 => {
            let n2 = 0.5 + NOISE_SCALE * value_gradient_noise(p);
            (GENERATOR1.0 * n2 + GENERATOR1.1).clamp(0.0, 1.0)
        }
        3 => (0.5 + GENERATOR3_SCALE * gradient_noise(p, GENERATOR3_SEED)).clamp(0.0, 1.0),
        _ => noise(p),
    }
}

/// POV-Ray's `DNoise`: a vector noise, each component centred on zero.
pub fn dnoise(p: DVec3) -> DVec3 {
    let Some(cell) = LatticeCell::of(p * LATTICE) else {
        return DVec3::ZERO;
    };
    cell.gradients(0x1234_5678) * DNOISE_SCALE
}

/// The scalar fractal sum POV-Ray's marble and agate use: noise mapped to [-1, 1] at
/// rising frequencies (times lambda) and falling weights (times omega). The [-1, 1] range
/// is what makes marble's spectrum match povray's (with [0, 1] it has a third of the power).
pub fn turbulence(p: DVec3, t: &Turbulence) -> f64 {
    fractal_sum(p, t, |q| 2.0 * noise(q) - 1.0)
}

/// Octaves of `f` at rising frequencies (times lambda) and falling weights (times omega):
/// the sum every kind of turbulence shares.
#[inline]
fn fractal_sum<T>(p: DVec3, t: &Turbulence, f: impl Fn(DVec3) -> T) -> T
where
    T: Copy + std::ops::Add<Output = T> + std::ops::Mul<f64, Output = T>,
{
    let mut sum = f(p);
    let (mut l, mut o) = (t.lambda, t.omega);
    for _ in 1..t.octaves.max(1) {
        sum = sum + f(p * l) * o;
        l *= t.lambda;
        o *= t.omega;
    }
    sum
}

/// The noise a fog's turbulence sums: wider than a pattern's, a linear map of it fitted to
/// povray's fog. Read back from one-octave fog renders through `exp(-w (1 - k t))`, at
/// noise depths 10, 10.37 and 10.74 (the noise's spread moves with the depth, in both
/// renderers alike), povray's values have median 0.51 to 0.52 and a 5%-95% width 1.085
/// times narrower, on average, than 2.196 n - 0.588, whose width matches pattern noise's
/// quantiles; the gain is scaled by that and the median kept.
const FOG_NOISE: (f64, f64) = (2.024, -0.502);

/// The scalar fractal sum a fog's turbulence reads (see render::fog).
pub fn fog_turbulence(p: DVec3, t: &Turbulence) -> f64 {
    fractal_sum(p, t, |q| FOG_NOISE.0 * noise(q) + FOG_NOISE.1)
}

/// The vector fractal sum that warps points (`turbulence`, `warp { turbulence }`).
pub fn dturbulence(p: DVec3, t: &Turbulence) -> DVec3 {
    fractal_sum(p, t, dnoise)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A corner that cells share has one hash, whichever cell asks: the noise is
    /// continuous across cell faces.
    #[test]
    fn cells_agree_on_their_shared_corners() {
        for (n, &(i, j, k)) in [(0, 0, 0), (-1, 5, -7), (123_456, -98_765, 3), (-1, -1, -1)]
            .iter()
            .enumerate()
        {
            let seed = 0x5eed_0001 ^ n as u32;
            let hashes = corner_hashes(i, j, k, seed);
            for (corner, &h) in hashes.iter().enumerate() {
                let d = |bit: usize| ((corner >> bit) & 1) as i64;
                assert_eq!(h, corner_hashes(i + d(0), j + d(1), k + d(2), seed)[0]);
            }
        }
    }

    /// The 4-bit fields the noises read (gradient codes at bits 0, 4 and 8; the top bits of
    /// the 16-bit values) are uniform and independent between a corner and each of the
    /// others, and between fields of one hash: the 256 pairs of two fields over 20,000
    /// cells pass a chi-square test at the 0.1% level (255 degrees of freedom: 330.5). The
    /// folded forms without their hash fail it.
    #[test]
    fn corner_fields_are_uniform_and_independent() {
        const CELLS: usize = 20_000;
        let chi_square = |pairs: &mut dyn Iterator<Item = (u32, u32)>| {
            let mut counts = [0u32; 256];
            for (a, b) in pairs {
                counts[((a & 15) << 4 | (b & 15)) as usize] += 1;
            }
            let expected = CELLS as f64 / 256.0;
            counts
                .iter()
                .map(|&c| (f64::from(c) - expected).powi(2) / expected)
                .sum::<f64>()
        };
        let cells: Vec<[u32; 8]> = (0..CELLS as i64)
            .map(|n| corner_hashes(n % 37 - 18, n / 37 % 29 - 14, n / 1073 - 9, 0x5eed_0001))
            .collect();
        for shift in [0, 4, 8, 12, 28] {
            for other in 1..8 {
                let x2 = chi_square(&mut cells.iter().map(|h| (h[0] >> shift, h[other] >> shift)));
                assert!(x2 < 330.5, "bits {shift}.., corners 0 and {other}: {x2}");
            }
        }
        for (s, t) in [(0, 4), (4, 8), (0, 8), (0, 16), (12, 28)] {
            let x2 = chi_square(&mut cells.iter().map(|h| (h[3] >> s, h[3] >> t)));
            assert!(x2 < 330.5, "bits {s}.. and {t}.. of one hash: {x2}");
        }
    }

    /// The table's gradients are improved Perlin noise's twelve edge directions (and four
    /// repeats), to the last bit of each dot product, whatever the code's high bits.
    #[test]
    fn gradient_codes_give_the_edge_directions() {
        let edge = |h: u32, x: f64, y: f64, z: f64| match h & 15 {
            0 | 12 => x + y,
            1 | 14 => -x + y,
            2 => x - y,
            3 => -x - y,
            4 => x + z,
            5 => -x + z,
            6 => x - z,
            7 => -x - z,
            8 => y + z,
            9 | 13 => -y + z,
            10 => y - z,
            _ => -y - z,
        };
        let mut h = 0x2545_f491u32;
        for n in 0..4096 {
            h = hash(h ^ n);
            let d = [
                f64::from(h % 1000) / 999.0 - 0.5,
                f64::from(hash(h) % 1000) / 999.0 - 1.0,
                f64::from(hash(h ^ 7) % 1000) / 999.0,
            ];
            assert_eq!(
                grad(h, d).to_bits(),
                edge(h, d[0], d[1], d[2]).to_bits(),
                "code {} at {d:?}",
                h & 15
            );
        }
    }

    #[test]
    fn noise_stays_in_range() {
        let mut lo: f64 = 1.0;
        let mut hi: f64 = 0.0;
        for i in 0..20000 {
            let p = DVec3::new(
                i as f64 * 0.37,
                i as f64 * 0.13 - 50.0,
                (i % 97) as f64 * 0.71,
            );
            let n = noise(p);
            lo = lo.min(n);
            hi = hi.max(n);
        }
        assert!(
            (0.0..0.3).contains(&lo) && (0.7..=1.0).contains(&hi),
            "{lo} {hi}"
        );
        assert_eq!(noise(DVec3::splat(f64::NAN)), 0.5);
    }

    #[test]
    fn generator_1_is_generator_2_without_range_correction() {
        // povray: bozo's generator-1 quantiles = 2.0414 x generator 2's - 0.5524.
        for i in 0..200 {
            let p = DVec3::new(i as f64 * 0.37, 1.3, i as f64 * 0.11);
            let (n1, n2) = (noise_with(p, 1), noise_with(p, 2));
            if n1 > 0.0 && n1 < 1.0 {
                assert!((n1 - (2.0414 * n2 - 0.5524)).abs() < 1e-9);
            }
            assert!((0.0..=1.0).contains(&noise_with(p, 3)));
        }
        assert_eq!(
            noise_with(DVec3::new(0.2, 0.4, 0.6), 2),
            noise(DVec3::new(0.2, 0.4, 0.6))
        );
    }

    #[test]
    fn noise_is_continuous() {
        let p = DVec3::new(0.3, 1.7, -2.2);
        let d = noise(p + DVec3::splat(1e-7)) - noise(p);
        assert!(d.abs() < 1e-5);
    }
}
