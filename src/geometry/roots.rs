//! Real roots of low-degree polynomials, robust enough for ray tracing: quadratics without
//! cancellation, and higher degrees by isolating each root between the roots of the
//! derivative (so every interval is monotone) and then bisecting with Newton steps.

/// A handful of roots, sorted, without allocation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Roots {
    pub values: [f64; 4],
    pub len: usize,
}

impl Roots {
    pub fn push(&mut self, t: f64) {
        if self.len < 4 {
            self.values[self.len] = t;
            self.len += 1;
        }
    }

    pub fn as_slice(&self) -> &[f64] {
        &self.values[..self.len]
    }

    pub fn sort(&mut self) {
        let n = self.len;
        self.values[..n].sort_by(f64::total_cmp);
    }
}

/// Roots of a t^2 + b t + c, ordered; q = -(b + sign(b) sqrt(disc))/2 avoids cancellation.
pub fn quadratic(a: f64, b: f64, c: f64) -> Roots {
    let mut r = Roots::default();
    if a == 0.0 {
        if b != 0.0 {
            r.push(-c / b);
        }
        return r;
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return r;
    }
    pair_from_q(-0.5 * (b + b.signum() * disc.sqrt()), a, c)
}

/// Both roots of a t^2 + b t + c from q = -(b + sign(b) sqrt(disc)) / 2: q / a and c / q,
/// ordered. Each is computed without subtracting nearly equal numbers.
pub fn pair_from_q(q: f64, a: f64, c: f64) -> Roots {
    let mut r = Roots::default();
    if q == 0.0 {
        r.push(0.0);
        r.push(0.0);
        return r;
    }
    let (t0, t1) = (q / a, c / q);
    r.push(t0.min(t1));
    r.push(t0.max(t1));
    r
}

/// Horner's rule from 0: the same operations in the same order whatever the length, the
/// commonest lengths (a quartic's and its derivatives') written out, as the loop over a
/// slice of unknown length was a fifth of the roots' instructions.
fn eval(coef: &[f64], t: f64) -> f64 {
    let h = |acc: f64, c: f64| acc * t + c;
    match *coef {
        [a, b, c, d, e] => h(h(h(h(h(0.0, a), b), c), d), e),
        [a, b, c, d] => h(h(h(h(0.0, a), b), c), d),
        [a, b, c] => h(h(h(0.0, a), b), c),
        _ => coef.iter().fold(0.0, |acc, &c| h(acc, c)),
    }
}

/// A bound on the rounding error of [`eval`] at t: Horner's rule for degree n errs by at
/// most 2 n unit roundoffs of the sum of the terms' magnitudes (Higham, Accuracy and
/// Stability of Numerical Algorithms, 5.1); this takes 2 (n + 1) machine epsilons, twice
/// that and more.
fn rounding_error(coef: &[f64], t: f64) -> f64 {
    let at = t.abs();
    let size = coef.iter().fold(0.0, |acc, &c| acc * at + c.abs());
    2.0 * coef.len() as f64 * f64::EPSILON * size
}

/// Fujiwara's bound on the size of every root (highest coefficient first): the walk's
/// bisections then start from an interval the roots need, not from the far reach.
pub fn root_bound(coef: &[f64]) -> f64 {
    let Some(lead) = coef.iter().position(|&c| c != 0.0) else {
        return 0.0;
    };
    let (a, rest) = (coef[lead], &coef[lead + 1..]);
    let n = rest.len();
    let bound = rest
        .iter()
        .enumerate()
        .map(|(k, &c)| {
            let ratio = (c / a).abs();
            if k + 1 == n {
                (ratio * 0.5).powf(1.0 / n as f64)
            } else {
                ratio.powf(1.0 / (k + 1) as f64)
            }
        })
        .fold(0.0, f64::max);
    2.0 * bound * (1.0 + 1e-9) + 1e-300
}

/// Roots in [lo, hi] of the polynomial with coefficients `coef` (highest degree first,
/// degree at most 4).
pub fn roots_in(coef: &[f64], lo: f64, hi: f64) -> Roots {
    let mut out = Roots::default();
    roots_until(coef, lo, hi, |t| {
        out.push(t);
        true
    });
    out
}

/// The roots of [`roots_in`] given to `take` in increasing order until it returns false:
/// a ray that wants its first crossing ahead (or any before a shadow ray's end) stops
/// there, and the pieces after it are never searched. The roots given are those
/// `roots_in` finds, bit for bit.
pub fn roots_until(coef: &[f64], lo: f64, hi: f64, mut take: impl FnMut(f64) -> bool) {
    // Drop leading zeros.
    let start = coef.iter().position(|&c| c != 0.0).unwrap_or(coef.len());
    let coef = &coef[start..];
    let degree = coef.len().saturating_sub(1);
    if degree == 0 {
        return;
    }
    if degree <= 2 {
        let r = if degree == 2 {
            quadratic(coef[0], coef[1], coef[2])
        } else {
            quadratic(0.0, coef[0], coef[1])
        };
        for &t in r.as_slice() {
            if t >= lo && t <= hi && !take(t) {
                return;
            }
        }
        return;
    }
    // Critical points split [lo, hi] into monotone pieces with at most one root each.
    let mut derivative = [0.0; 4];
    for (i, c) in coef[..degree].iter().enumerate() {
        derivative[i] = c * (degree - i) as f64;
    }
    let derivative = &derivative[..degree];
    let critical = roots_in(derivative, lo, hi);
    monotone_roots(coef, derivative, (lo, hi), critical.as_slice(), take);
}

/// Up to seven roots, sorted, without allocation (for the degree-6 polynomials of lathes
/// and the degree-7 ones of `poly`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WideRoots {
    pub values: [f64; 7],
    pub len: usize,
}

impl WideRoots {
    fn push(&mut self, t: f64) {
        if self.len < 7 {
            self.values[self.len] = t;
            self.len += 1;
        }
    }

    pub fn as_slice(&self) -> &[f64] {
        &self.values[..self.len]
    }
}

/// Roots in [lo, hi] (finite) of a polynomial of degree at most 7, highest degree first,
/// found as [`roots_in`] finds them: between the roots of the derivative, each interval
/// monotone.
pub fn roots_in_wide(coef: &[f64], lo: f64, hi: f64) -> WideRoots {
    debug_assert!(coef.len() <= 8, "degree above 7");
    let start = coef.iter().position(|&c| c != 0.0).unwrap_or(coef.len());
    let coef = &coef[start..];
    let degree = coef.len().saturating_sub(1);
    let mut out = WideRoots::default();
    if degree <= 4 {
        for &t in roots_in(coef, lo, hi).as_slice() {
            out.push(t);
        }
        return out;
    }
    let mut derivative = [0.0; 7];
    for (i, c) in coef[..degree].iter().enumerate() {
        derivative[i] = c * (degree - i) as f64;
    }
    let derivative = &derivative[..degree];
    let critical = roots_in_wide(derivative, lo, hi);
    monotone_roots(coef, derivative, (lo, hi), critical.as_slice(), |t| {
        out.push(t);
        true
    });
    out
}

/// The roots in [lo, hi] of a polynomial whose sorted critical points there are `critical`
/// (the roots of `derivative`, whose coefficients serve every piece's Newton steps): one
/// per monotone piece between them, in increasing order, a root shared by two pieces given
/// once, until `push` returns false.
fn monotone_roots(
    coef: &[f64],
    derivative: &[f64],
    (lo, hi): (f64, f64),
    critical: &[f64],
    mut push: impl FnMut(f64) -> bool,
) {
    let mut last: Option<f64> = None;
    // False once `push` has asked to stop.
    let mut piece = |a: f64, b: f64| {
        if let Some(t) = monotone_root(coef, derivative, a, b)
            && last.is_none_or(|l| (t - l).abs() > 1e-12 * t.abs().max(1.0))
        {
            last = Some(t);
            return push(t);
        }
        true
    };
    let mut a = lo;
    for &c in critical {
        if c > a {
            if !piece(a, c) {
                return;
            }
            a = c;
        }
    }
    piece(a, hi);
}

/// The root of a polynomial that is monotone on [a, b], if its sign changes there
/// (`derivative`: its derivative's coefficients).
fn monotone_root(coef: &[f64], derivative: &[f64], mut a: f64, mut b: f64) -> Option<f64> {
    let mut fa = eval(coef, a);
    let fb = eval(coef, b);
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if fa.signum() == fb.signum() {
        return None;
    }
    // An end where the value is within its own rounding error is the root: the sign
    // change is then rounding's, and the search inside bisected down to that end, 25 to
    // 50 steps (objects/blob1a.pov: a fifth of its pieces with a root).
    let (end, f_end) = if fa.abs() <= fb.abs() {
        (a, fa)
    } else {
        (b, fb)
    };
    if f_end.abs() <= rounding_error(coef, end) {
        return Some(end);
    }
    let mut t = 0.5 * (a + b);
    for _ in 0..100 {
        let f = eval(coef, t);
        if f == 0.0 {
            return Some(t);
        }
        if f.signum() == fa.signum() {
            a = t;
            fa = f;
        } else {
            b = t;
        }
        // A Newton step, kept only if it stays inside the bracket.
        let df = eval(derivative, t);
        let newton = t - f / df;
        let tolerance = 1e-15 * (a.abs() + b.abs()).max(1e-300);
        if df != 0.0 && newton > a && newton < b {
            // Newton closes in from one side and leaves the bracket wide: stop on its step.
            let step = (newton - t).abs();
            t = newton;
            if step <= tolerance {
                break;
            }
        } else {
            t = 0.5 * (a + b);
        }
        if (b - a) <= tolerance {
            break;
        }
    }
    Some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quartic_with_four_roots() {
        // (t-1)(t-2)(t-3)(t-4) = t^4 - 10t^3 + 35t^2 - 50t + 24
        let r = roots_in(&[1.0, -10.0, 35.0, -50.0, 24.0], -10.0, 10.0);
        assert_eq!(r.len, 4);
        for (got, want) in r.as_slice().iter().zip([1.0, 2.0, 3.0, 4.0]) {
            assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        }
    }

    /// `roots_until` gives `roots_in`'s roots, bit for bit and in order, and stops when
    /// told: (t - 1)(t - 2)(t - 3)(t - 4) and a quartic of two close roots.
    #[test]
    fn roots_until_gives_the_same_roots_and_stops() {
        for (p, lo, hi) in [
            ([1.0, -10.0, 35.0, -50.0, 24.0], -10.0, 10.0),
            ([1.0, -2.001, 2.001, -2.001, 1.001], 0.0, 5.0),
            ([0.0, 1.0, -6.0, 11.0, -6.0], 0.5, 2.5),
        ] {
            let all = roots_in(&p, lo, hi);
            let mut given = Vec::new();
            roots_until(&p, lo, hi, |t| {
                given.push(t);
                true
            });
            assert_eq!(given, all.as_slice(), "{p:?}");
            for stop in 1..=all.len {
                let mut taken = Vec::new();
                roots_until(&p, lo, hi, |t| {
                    taken.push(t);
                    taken.len() < stop
                });
                assert_eq!(taken, all.as_slice()[..stop], "{p:?} stopping after {stop}");
            }
        }
    }

    #[test]
    fn close_roots_and_ranges() {
        // (t - 1)(t - 1.001)(t^2 + 1)
        let p = [1.0, -2.001, 2.001, -2.001, 1.001];
        let r = roots_in(&p, 0.0, 5.0);
        assert_eq!(r.len, 2, "{r:?}");
        assert!((r.values[0] - 1.0).abs() < 1e-9 && (r.values[1] - 1.001).abs() < 1e-9);
        assert_eq!(roots_in(&p, 2.0, 5.0).len, 0);
    }

    #[test]
    fn sextic_with_six_roots() {
        // (t - 1)(t - 2)...(t - 6), expanded.
        let p = [1.0, -21.0, 175.0, -735.0, 1624.0, -1764.0, 720.0];
        let r = roots_in_wide(&p, 0.0, 10.0);
        assert_eq!(r.len, 6, "{r:?}");
        for (got, want) in r.as_slice().iter().zip(1..=6) {
            assert!((got - want as f64).abs() < 1e-9, "{got} vs {want}");
        }
        assert_eq!(roots_in_wide(&p, 2.5, 4.5).len, 2);
    }

    /// The coefficients (highest first) of the product of (t - r) over `roots`.
    fn from_roots(roots: &[f64]) -> Vec<f64> {
        let mut p = vec![1.0];
        for &r in roots {
            let mut next = vec![0.0; p.len() + 1];
            for (i, c) in p.iter().enumerate() {
                next[i] += c;
                next[i + 1] -= c * r;
            }
            p = next;
        }
        p
    }

    #[test]
    fn degree_seven_with_seven_roots() {
        let want = [-2.5, -1.0, -0.25, 0.5, 1.5, 2.0, 3.75];
        let r = roots_in_wide(&from_roots(&want), -10.0, 10.0);
        assert_eq!(r.len, 7, "{r:?}");
        for (got, want) in r.as_slice().iter().zip(want) {
            assert!((got - want).abs() < 1e-9, "{got} vs {want}");
        }
    }

    #[test]
    fn near_double_roots_of_degree_five_to_seven() {
        // Two roots 1e-4 apart beside simple ones, with a pair of complex roots in the
        // degree-7 case (times t^2 + 1).
        let close = [0.7, 0.7001];
        for (extra, complex) in [
            (&[-1.0, 2.0, 3.0][..], false),
            (&[-1.0, 2.0, 3.0, 4.0], false),
            (&[-1.0, 2.0, 3.0, 4.0, 5.0], false),
            (&[-2.0, 1.5, 3.0], true),
        ] {
            let mut roots: Vec<f64> = close.iter().chain(extra).copied().collect();
            let mut p = from_roots(&roots);
            if complex {
                // (t^2 + 1) p: two roots off the real line.
                let mut q = vec![0.0; p.len() + 2];
                for (i, c) in p.iter().enumerate() {
                    q[i] += c;
                    q[i + 2] += c;
                }
                p = q;
            }
            roots.sort_by(f64::total_cmp);
            let r = roots_in_wide(&p, -10.0, 10.0);
            assert_eq!(r.as_slice().len(), roots.len(), "{r:?} for {roots:?}");
            for (got, want) in r.as_slice().iter().zip(&roots) {
                assert!((got - want).abs() < 1e-7, "{got} vs {want}");
            }
        }
    }

    /// A root at an end of the interval searched, where the polynomial's computed value is
    /// rounding's and not 0, is that end (from either side where the values' signs
    /// differ), not a point found by bisecting towards it.
    #[test]
    fn a_root_at_an_end_within_rounding_is_the_end() {
        let mut checked = 0;
        for k in 1..40 {
            // (t - r)(t - 2)(t + 3): at the double nearest r the value is a residue.
            let r = f64::from(k) * 0.137;
            let p = from_roots(&[r, 7.0, -3.0]);
            let at = eval(&p, r);
            if at == 0.0 {
                continue;
            }
            assert!(at.abs() <= rounding_error(&p, r), "{at} at {r}");
            for (lo, hi) in [(r, r + 0.01), (r - 0.01, r)] {
                if eval(&p, lo).signum() != eval(&p, hi).signum() {
                    assert_eq!(roots_in(&p, lo, hi).as_slice(), [r], "[{lo}, {hi}]");
                    checked += 1;
                }
            }
        }
        assert!(checked > 5, "only {checked} cases");
    }

    #[test]
    fn an_exact_double_root_is_found_at_most_once() {
        // (t - 1)^2 (t + 2)(t - 3)(t - 4): the tangency gives one root or none, never two
        // far apart.
        let p = from_roots(&[1.0, 1.0, -2.0, 3.0, 4.0]);
        let r = roots_in_wide(&p, -10.0, 10.0);
        let near_one: Vec<f64> = r
            .as_slice()
            .iter()
            .copied()
            .filter(|t| (t - 1.0).abs() < 1e-3)
            .collect();
        assert!(near_one.len() <= 1, "{r:?}");
        assert_eq!(r.len - near_one.len(), 3, "{r:?}");
    }

    proptest::proptest! {
        #[test]
        fn separated_roots_of_degree_five_to_seven_are_all_found(
            raw in proptest::collection::vec(-4.0f64..4.0, 5..=7),
            scale in 0.5f64..3.0,
        ) {
            let mut roots: Vec<f64> = raw;
            roots.sort_by(f64::total_cmp);
            // Keep them at least 0.05 apart so each is simple.
            for i in 1..roots.len() {
                if roots[i] - roots[i - 1] < 0.05 {
                    roots[i] = roots[i - 1] + 0.05;
                }
            }
            let p: Vec<f64> = from_roots(&roots).iter().map(|c| c * scale).collect();
            let r = roots_in_wide(&p, -20.0, 20.0);
            proptest::prop_assert_eq!(r.len, roots.len(), "{:?} for {:?}", r, roots);
            for (got, want) in r.as_slice().iter().zip(&roots) {
                proptest::prop_assert!((got - want).abs() < 1e-7, "{} vs {}", got, want);
            }
        }
    }

    #[test]
    fn stable_quadratic() {
        let r = quadratic(1.0, -1e8, 1.0);
        assert!((r.values[0] - 1e-8).abs() < 1e-20);
    }
}
