//! Distribution statistics for comparing noisy textures with POV-Ray's: quantiles of the
//! values and radially averaged power spectra in octave bands. Noise-based patterns cannot
//! match POV-Ray point by point (its noise tables are its own), so they are compared this
//! way (tests/appearance_noise.rs, tests/appearance_normals.rs, scripts/noise_reference.py
//! computes the same figures for povray's renders).

/// The rows of a statistics table written by scripts/noise_reference.py or
/// scripts/normal_reference.py: `|`-separated fields, `#` comments and blank lines skipped.
pub fn table_rows(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| l.split('|').map(str::trim).collect())
        .collect()
}

/// The numbers of a space-separated field, or None if one does not parse.
pub fn numbers(field: &str) -> Option<Vec<f64>> {
    field.split_whitespace().map(|v| v.parse().ok()).collect()
}

/// numpy's default (linear) quantile of sorted values.
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    let h = (sorted.len() - 1) as f64 * q;
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(sorted.len() - 1);
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}

fn fft(re: &mut [f64], im: &mut [f64]) {
    let n = re.len();
    let mut j = 0;
    for i in 1..n {
        let mut bit = n >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            re.swap(i, j);
            im.swap(i, j);
        }
    }
    let mut len = 2;
    while len <= n {
        let ang = -2.0 * std::f64::consts::PI / len as f64;
        for start in (0..n).step_by(len) {
            for k in 0..len / 2 {
                let (s, c) = (ang * k as f64).sin_cos();
                let (a, b) = (start + k, start + k + len / 2);
                let tr = re[b] * c - im[b] * s;
                let ti = re[b] * s + im[b] * c;
                re[b] = re[a] - tr;
                im[b] = im[a] - ti;
                re[a] += tr;
                im[a] += ti;
            }
        }
        len <<= 1;
    }
}

/// Mean of |F|^2 / N over each radial band of a `size` x `size` image covering `extent`
/// units, bands given by their edges in cycles per unit (`size` a power of two).
pub fn band_powers(img: &[f64], size: usize, extent: f64, bands: &[f64]) -> Vec<f64> {
    let mean = img.iter().sum::<f64>() / img.len() as f64;
    let mut re: Vec<f64> = img.iter().map(|v| v - mean).collect();
    let mut im = vec![0.0; re.len()];
    for r in 0..size {
        fft(
            &mut re[r * size..(r + 1) * size],
            &mut im[r * size..(r + 1) * size],
        );
    }
    let (mut cr, mut ci) = (vec![0.0; size], vec![0.0; size]);
    for c in 0..size {
        for r in 0..size {
            cr[r] = re[r * size + c];
            ci[r] = im[r * size + c];
        }
        fft(&mut cr, &mut ci);
        for r in 0..size {
            re[r * size + c] = cr[r];
            im[r * size + c] = ci[r];
        }
    }
    let freq = |k: usize| {
        let k = if k < size / 2 {
            k as f64
        } else {
            k as f64 - size as f64
        };
        k / extent
    };
    let mut sums = vec![0.0; bands.len() - 1];
    let mut counts = vec![0usize; bands.len() - 1];
    for r in 0..size {
        for c in 0..size {
            let k = freq(r).hypot(freq(c));
            if let Some(b) = bands.windows(2).position(|w| k >= w[0] && k < w[1]) {
                let i = r * size + c;
                sums[b] += (re[i] * re[i] + im[i] * im[i]) / img.len() as f64;
                counts[b] += 1;
            }
        }
    }
    sums.iter()
        .zip(&counts)
        .map(|(s, &n)| s / n.max(1) as f64)
        .collect()
}

/// Two-sided Student t critical value for a family-wise level `alpha` over `tests` tests
/// (Sidak), at `df` degrees of freedom: the normal quantile corrected by the Cornish-Fisher
/// expansion of t in 1/df (Abramowitz & Stegun 26.7.5), within 1% of t for df >= 10 at
/// these levels.
pub fn student_critical(alpha: f64, tests: usize, df: f64) -> f64 {
    let per_test = 1.0 - (1.0 - alpha).powf(1.0 / tests as f64);
    let z = normal_quantile(1.0 - per_test / 2.0);
    let (z3, z5, z7, z9) = (z.powi(3), z.powi(5), z.powi(7), z.powi(9));
    z + (z3 + z) / (4.0 * df)
        + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * df * df)
        + (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / (384.0 * df.powi(3))
        + (79.0 * z9 + 776.0 * z7 + 1482.0 * z5 - 1920.0 * z3 - 945.0 * z) / (92160.0 * df.powi(4))
}

/// The standard normal quantile, by bisection of erfc (exact enough for critical values).
pub fn normal_quantile(p: f64) -> f64 {
    let (mut lo, mut hi) = (-10.0f64, 10.0f64);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if 1.0 - 0.5 * erfc(mid / std::f64::consts::SQRT_2) < p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// erfc by its continued-fraction-free Chebyshev fit (Numerical Recipes' erfcc, relative
/// error below 1.2e-7 everywhere).
pub fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = -z * z - 1.265_512_23
        + t * (1.000_023_68
            + t * (0.374_091_96
                + t * (0.096_784_18
                    + t * (-0.186_288_06
                        + t * (0.278_868_07
                            + t * (-1.135_203_98
                                + t * (1.488_515_87 + t * (-0.822_152_23 + t * 0.170_872_77))))))));
    let r = t * poly.exp();
    if x >= 0.0 { r } else { 2.0 - r }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_skip_comments_and_split_fields() {
        let rows = table_rows("# name | values\n\nbozo | 0.1 0.2 | x\n");
        assert_eq!(rows, vec![vec!["bozo", "0.1 0.2", "x"]]);
        assert_eq!(numbers(rows[0][1]), Some(vec![0.1, 0.2]));
        assert_eq!(numbers(rows[0][2]), None);
    }

    #[test]
    fn quantiles_interpolate_like_numpy() {
        let v = [0.0, 1.0, 2.0, 3.0, 4.0];
        assert_eq!(quantile(&v, 0.0), 0.0);
        assert_eq!(quantile(&v, 0.5), 2.0);
        assert!((quantile(&v, 0.3) - 1.2).abs() < 1e-12);
    }

    #[test]
    fn a_sine_puts_its_power_in_its_band() {
        // 64 x 64 over 8 units: a wave of 3 cycles per unit along x lies in band [2, 4).
        let (size, extent) = (64, 8.0);
        let img: Vec<f64> = (0..size * size)
            .map(|i| {
                let x = (i % size) as f64 * extent / size as f64;
                (std::f64::consts::TAU * 3.0 * x).sin()
            })
            .collect();
        let p = band_powers(&img, size, extent, &[0.5, 1.0, 2.0, 4.0]);
        assert!(p[2] > 0.0);
        assert!(p[0] < 1e-20 && p[1] < 1e-20, "{p:?}");
    }

    #[test]
    fn critical_values_are_students() {
        // Tables: t(0.975; 10) = 2.2281, t(0.995; 20) = 2.8453, z(0.975) = 1.95996.
        assert!((student_critical(0.05, 1, 10.0) - 2.2281).abs() < 0.01);
        assert!((student_critical(0.01, 1, 20.0) - 2.8453).abs() < 0.005);
        assert!((student_critical(0.05, 1, 1e9) - 1.95996).abs() < 1e-4);
        // Sidak over 39 tests at 1e-3 with df = 15: wider than the normal's 4.2.
        let t = student_critical(1e-3, 39, 15.0);
        assert!(t > 4.3 && t < 7.0, "{t}");
    }
}
