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
    #[inline(always)]
    fn size(coef: &[f64], at: f64) -> f64 {
        coef.iter().fold(0.0, |acc, &c| acc * at + c.abs())
    }
    let at = t.abs();
    let size = match *coef {
        [a, b, c, d, e] => size(&[a, b, c, d, e], at),
        [a, b, c, d] => size(&[a, b, c, d], at),
        _ => size(coef, at),
    };
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
    let mut bound = 0.0f64;
    for (k, &c) in rest.iter().enumerate() {
        let ratio = (c / a).abs();
        let (x, root) = if k + 1 == n {
            (ratio * 0.5, n)
        } else {
            (ratio, k + 1)
        };
        // A root taken only where it may raise the bound (a cube root is 140 instructions).
        if x > bound.powi(root as i32) {
            bound = bound.max(nth_root(x, root));
        }
    }
    2.0 * bound * (1.0 + 1e-9) + 1e-300
}

/// x^(1/n), by square and cube roots where they serve (the library's `powf` was 4% of a
/// quartic scene's instructions); the bound's 1e-9 margin covers their last bits.
fn nth_root(x: f64, n: usize) -> f64 {
    match n {
        1 => x,
        2 => x.sqrt(),
        3 => x.cbrt(),
        4 => x.sqrt().sqrt(),
        _ => x.powf(1.0 / n as f64),
    }
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
    debug_assert!(coef.len() <= 5, "degree above 4");
    let Ok(quartic) = <&[f64; 5]>::try_from(coef) else {
        cubic_until(coef, lo, hi, take);
        return;
    };
    // A quartic: its critical points (the cubic derivative's roots) arrive in increasing
    // order and each monotone piece is searched as soon as its end is known, so a ray
    // stopping at its first crossing has the critical points beyond it never found.
    let derivative = derivative_of::<4>(coef);
    let mut walk = MonotoneWalk::new(quartic, lo);
    if cubic_until(&derivative, lo, hi, |c| walk.critical(c, &mut take)) {
        walk.finish(hi, &mut take);
    }
}

/// [`roots_until`] for a polynomial of degree at most 3 without leading zeros; false when
/// `take` asked to stop.
fn cubic_until(coef: &[f64], lo: f64, hi: f64, mut take: impl FnMut(f64) -> bool) -> bool {
    let Ok(cubic) = <&[f64; 4]>::try_from(coef) else {
        let r = match *coef {
            [a, b, c] => quadratic(a, b, c),
            [b, c] => quadratic(0.0, b, c),
            _ => return true,
        };
        return r
            .as_slice()
            .iter()
            .all(|&t| !(t >= lo && t <= hi) || take(t));
    };
    let derivative = derivative_of::<3>(coef);
    let critical = quadratic(derivative[0], derivative[1], derivative[2]);
    let mut walk = MonotoneWalk::new(cubic, lo);
    for &c in critical.as_slice() {
        if c >= lo && c <= hi && !walk.critical(c, &mut take) {
            return false;
        }
    }
    walk.finish(hi, &mut take)
}

/// C(i, k) / C(n, k) for degree n up to 4: the weights that turn the power basis on
/// [0, 1] into Bernstein coefficients.
const BERNSTEIN: [[[f64; 5]; 5]; 5] = {
    let mut t = [[[0.0; 5]; 5]; 5];
    let mut n = 0;
    while n < 5 {
        let mut i = 0;
        while i <= n {
            let mut k = 0;
            while k <= i {
                t[n][i][k] = binomial(i, k) / binomial(n, k);
                k += 1;
            }
            i += 1;
        }
        n += 1;
    }
    t
};

const fn binomial(n: usize, k: usize) -> f64 {
    let (mut c, mut j) = (1.0, 0);
    while j < k {
        c = c * (n - j) as f64 / (j + 1) as f64;
        j += 1;
    }
    c
}

/// Whether the polynomial (`N` coefficients, highest first, degree at most 4) is certainly
/// of one sign over [lo, hi] (finite), by a margin wider than any rounding of its values:
/// then the search would find no sign change there either. The test is the signs of the
/// Bernstein coefficients over the interval (every value there is their weighted mean),
/// about 60 operations where the search costs hundreds. It pays where most intervals hold
/// no root (a blob's ray meets many spheres of influence and crosses the surface in few of
/// them); tried before every quartic and cubic search it cost more than it saved (prism3c
/// +5.6%, sor1 +1.6%, partorus +1.2% instructions; lathe2 -2.7%).
pub fn keeps_sign<const N: usize>(coef: &[f64; N], lo: f64, hi: f64) -> bool {
    let width = hi - lo;
    if !(width.is_finite() && lo.is_finite() && (2..=5).contains(&N)) {
        return false;
    }
    // Ascending coefficients of p(lo + width s).
    let mut a: [f64; N] = std::array::from_fn(|k| coef[N - 1 - k]);
    for i in 0..N - 1 {
        for j in (i..N - 1).rev() {
            a[j] += lo * a[j + 1];
        }
    }
    let mut scale = 1.0;
    for x in a.iter_mut() {
        *x *= scale;
        scale *= width;
    }
    // Wider than the values' rounding anywhere in the interval ([`rounding_error`] at its
    // far end bounds it) and than the coefficients' own here.
    let margin = 128.0 * rounding_error(coef, lo.abs().max(hi.abs()));
    let (mut positive, mut negative) = (true, true);
    for (i, weights) in BERNSTEIN[N - 1].iter().enumerate().take(N) {
        // b_i = the sum over k <= i of C(i, k) / C(n, k) a_k.
        let b = (0..=i).fold(0.0, |b, k| b + weights[k] * a[k]);
        positive &= b > margin;
        negative &= b < -margin;
    }
    positive || negative
}

/// The derivative's coefficients of a polynomial of degree `N` (highest first).
fn derivative_of<const N: usize>(coef: &[f64]) -> [f64; N] {
    std::array::from_fn(|i| coef[i] * (N - i) as f64)
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
    let mut push = |t| {
        out.push(t);
        true
    };
    let range = (lo, hi);
    let _ = pieces_of::<6>(coef, range, critical.as_slice(), &mut push)
        || pieces_of::<7>(coef, range, critical.as_slice(), &mut push)
        || pieces_of::<8>(coef, range, critical.as_slice(), &mut push);
    out
}

/// [`monotone_roots`] for a polynomial of `N` coefficients (written for each length, as
/// the search's sums then unroll); false, doing nothing, for another length.
fn pieces_of<const N: usize>(
    coef: &[f64],
    range: (f64, f64),
    critical: &[f64],
    push: &mut impl FnMut(f64) -> bool,
) -> bool {
    let Ok(coef) = <&[f64; N]>::try_from(coef) else {
        return false;
    };
    monotone_roots(coef, range, critical, push);
    true
}

/// The roots in [lo, hi] of a polynomial whose sorted critical points there are `critical`:
/// one per monotone piece between them, in increasing order, a root shared by two pieces
/// given once, until `push` returns false.
fn monotone_roots<const N: usize>(
    coef: &[f64; N],
    (lo, hi): (f64, f64),
    critical: &[f64],
    push: &mut impl FnMut(f64) -> bool,
) {
    let mut walk = MonotoneWalk::new(coef, lo);
    for &c in critical {
        if !walk.critical(c, push) {
            return;
        }
    }
    walk.finish(hi, push);
}

/// A polynomial's monotone pieces searched in increasing order as its critical points
/// arrive: the piece a critical point closes is solved before the next one is looked for,
/// and the value at a piece's end is the next piece's start.
struct MonotoneWalk<'a, const N: usize> {
    coef: &'a [f64; N],
    /// The open piece's start and the polynomial's value there.
    a: f64,
    fa: f64,
    /// The last root given (one shared by two pieces is given once).
    last: Option<f64>,
}

impl<'a, const N: usize> MonotoneWalk<'a, N> {
    fn new(coef: &'a [f64; N], lo: f64) -> Self {
        MonotoneWalk {
            coef,
            a: lo,
            fa: eval(coef, lo),
            last: None,
        }
    }

    /// The next critical point, closing the open piece where it lies beyond its start;
    /// false once `push` has asked to stop.
    fn critical(&mut self, c: f64, push: &mut impl FnMut(f64) -> bool) -> bool {
        if c > self.a {
            let fc = eval(self.coef, c);
            if !self.piece(c, fc, push) {
                return false;
            }
            (self.a, self.fa) = (c, fc);
        }
        true
    }

    /// The last piece, to `hi`; false if `push` asked to stop.
    fn finish(mut self, hi: f64, push: &mut impl FnMut(f64) -> bool) -> bool {
        let fh = eval(self.coef, hi);
        self.piece(hi, fh, push)
    }

    fn piece(&mut self, b: f64, fb: f64, push: &mut impl FnMut(f64) -> bool) -> bool {
        let found = monotone_root(self.coef, (self.a, self.fa), (b, fb));
        if let Some(t) = found
            && self
                .last
                .is_none_or(|l| (t - l).abs() > 1e-12 * t.abs().max(1.0))
        {
            self.last = Some(t);
            return push(t);
        }
        true
    }
}

/// The root of a polynomial that is monotone on [a, b], if its sign changes there, given
/// its values at both ends.
///
/// From the end whose value is nearer zero, a first step of Laguerre's, then Newton's,
/// each kept while it stays inside the bracket (bisection otherwise). Newton's steps alone,
/// from the middle of a piece that runs to the far root bound, crept in by a quarter a step
/// (a quartic is t^4 from afar), and from a piece's end, a critical point, had no slope to
/// follow: 12 to 20 steps a root. Laguerre's step reads the curvature too and lands near
/// the root from either; after it Newton's converge as fast for less (one division where
/// Laguerre's takes two and a square root: Laguerre's throughout took fewer instructions but
/// more time). The search stops where the value is within its rounding error
/// ([`rounding_error`]): past that the sign is rounding's, and the steps wandered inside
/// the noise.
fn monotone_root<const N: usize>(
    coef: &[f64; N],
    (mut a, mut fa): (f64, f64),
    (mut b, fb): (f64, f64),
) -> Option<f64> {
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    // Signs compared by `< 0` (no value compared is 0; a NaN counts as positive), cheaper
    // than `signum`'s NaN test.
    if (fa < 0.0) == (fb < 0.0) {
        return None;
    }
    // An end where the value is within its own rounding error is the root: the sign
    // change is then rounding's (objects/blob1a.pov: a fifth of its pieces with a root).
    let (mut t, mut f) = if fa.abs() <= fb.abs() {
        (a, fa)
    } else {
        (b, fb)
    };
    if f.abs() <= rounding_error(coef, t) {
        return Some(t);
    }
    let degree = (coef.len() - 1) as f64;
    for k in 0..100 {
        let step = if k == 0 {
            laguerre_step(coef, degree, t, f)
        } else {
            (f / slopes(coef, t).0).abs()
        };
        // Towards the end whose sign differs from f's.
        let mut next = if (f < 0.0) == (fa < 0.0) {
            t + step
        } else {
            t - step
        };
        if !(next > a && next < b) {
            next = 0.5 * (a + b);
        }
        let moved = (next - t).abs();
        t = next;
        f = eval(coef, t);
        if f.abs() <= rounding_error(coef, t) {
            return Some(t);
        }
        if (f < 0.0) == (fa < 0.0) {
            (a, fa) = (t, f);
        } else {
            b = t;
        }
        let tolerance = 1e-15 * (a.abs() + b.abs()).max(1e-300);
        if moved <= tolerance || b - a <= tolerance {
            break;
        }
    }
    Some(t)
}

/// The length of Laguerre's step at t (value f there) for a polynomial of `degree`: exact
/// for a polynomial whose roots but one coincide, and cubically convergent near a simple
/// root (Press et al., Numerical Recipes, 9.5). Its direction is the bracket's to choose:
/// within a monotone piece it is the side where the sign changes.
#[inline]
fn laguerre_step(coef: &[f64], degree: f64, t: f64, f: f64) -> f64 {
    let (d1, d2) = slopes(coef, t);
    let inverse = 1.0 / f;
    let g = d1 * inverse;
    let h = g * g - d2 * inverse;
    // Below zero where complex roots pull: their real part's pull alone is taken.
    let spread = ((degree - 1.0) * (degree * h - g * g)).max(0.0).sqrt();
    degree / (g.abs() + spread)
}

/// The first and second derivatives at t, by Horner's rule carried two terms further
/// (written out for a quartic's and a cubic's length, which the compiler unrolls).
#[inline]
fn slopes(coef: &[f64], t: f64) -> (f64, f64) {
    #[inline(always)]
    fn carried(coef: &[f64], t: f64) -> (f64, f64) {
        let (mut value, mut d1, mut d2) = (0.0, 0.0, 0.0);
        for &c in coef {
            d2 = d2 * t + d1;
            d1 = d1 * t + value;
            value = value * t + c;
        }
        (d1, 2.0 * d2)
    }
    match *coef {
        [a, b, c, d, e] => carried(&[a, b, c, d, e], t),
        [a, b, c, d] => carried(&[a, b, c, d], t),
        _ => carried(coef, t),
    }
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

    /// Quartics of known roots, four real or two real beside a complex pair, at scales a
    /// ray's quartic takes (roots out to 1e3, coefficients to 1e12): every real root is
    /// found once, to within what the polynomial's rounding lets it be told (its value's
    /// rounding error over its slope there, or 1e-9 where two roots lie close).
    #[test]
    fn quartic_roots_are_found_to_their_rounding() {
        let mut next = crate::geometry::uniform_stream(5);
        let mut found = 0;
        for case in 0..2000 {
            let scale = 10f64.powf(3.0 * next());
            let mut real: Vec<f64> = (0..if case % 2 == 0 { 4 } else { 2 })
                .map(|_| scale * (2.0 * next() - 1.0))
                .collect();
            real.sort_by(f64::total_cmp);
            if real.windows(2).any(|w| w[1] - w[0] < 1e-3 * scale) {
                continue;
            }
            let mut p = from_roots(&real);
            if real.len() == 2 {
                // Times (t - re)^2 + im^2.
                let (re, im) = (scale * (2.0 * next() - 1.0), scale * (0.01 + next()));
                let q = [1.0, -2.0 * re, re * re + im * im];
                let mut product = vec![0.0; p.len() + 2];
                for (i, a) in p.iter().enumerate() {
                    for (j, b) in q.iter().enumerate() {
                        product[i + j] += a * b;
                    }
                }
                p = product;
            }
            let bound = root_bound(&p);
            assert!(real.iter().all(|r| r.abs() < bound), "{bound} for {real:?}");
            let got = roots_in(&p, -bound, bound);
            assert_eq!(got.as_slice().len(), real.len(), "{got:?} for {real:?}");
            for (&t, &want) in got.as_slice().iter().zip(&real) {
                let slope = eval(&[4.0 * p[0], 3.0 * p[1], 2.0 * p[2], p[3]], want).abs();
                let allowed = 4.0 * rounding_error(&p, want) / slope + 1e-12 * scale;
                assert!(
                    (t - want).abs() <= allowed,
                    "{t} vs {want} (allowed {allowed})"
                );
                found += 1;
            }
        }
        assert!(found > 4000, "{found} roots");
    }

    /// The sign test over an interval: never where a root lies inside, and where it holds,
    /// the values across the interval keep that sign; it holds over most root-free
    /// intervals of quartics and cubics of known roots (two complex when the degree is 4).
    #[test]
    fn keeps_sign_only_where_no_root_lies() {
        let mut next = crate::geometry::uniform_stream(13);
        let (mut held, mut free) = (0, 0);
        for case in 0..4000 {
            let real: Vec<f64> = (0..3).map(|_| 8.0 * next() - 4.0).collect();
            let p = if case % 2 == 0 {
                from_roots(&real)
            } else {
                // (t - r0)(t - r1)(t^2 + 1): a quartic with two real roots.
                let mut q = from_roots(&real[..2]);
                q.push(0.0);
                q.push(0.0);
                for i in (2..q.len()).rev() {
                    q[i] += q[i - 2];
                }
                q
            };
            let (lo, hi) = (8.0 * next() - 4.0, 8.0 * next() - 4.0);
            let (lo, hi) = (lo.min(hi), lo.max(hi));
            let holds = match p.len() {
                4 => keeps_sign(&<[f64; 4]>::try_from(p.as_slice()).unwrap(), lo, hi),
                _ => keeps_sign(&<[f64; 5]>::try_from(p.as_slice()).unwrap(), lo, hi),
            };
            let rootless = real
                .iter()
                .take(if p.len() == 4 { 3 } else { 2 })
                .all(|r| *r < lo || *r > hi);
            free += usize::from(rootless);
            if holds {
                assert!(rootless, "{p:?} over [{lo}, {hi}]");
                let sign = eval(&p, lo) > 0.0;
                for k in 0..=32 {
                    let t = lo + (hi - lo) * f64::from(k) / 32.0;
                    assert_eq!(eval(&p, t) > 0.0, sign, "{p:?} at {t}");
                }
                held += 1;
            }
        }
        assert!(
            held * 2 > free,
            "held over {held} of {free} root-free intervals"
        );
    }

    /// Fujiwara's bound with roots taken only where they may raise it is the bound with
    /// every root taken (by `powf`), to the last bits the cube root may differ in (that it
    /// holds every root, the test above checks).
    #[test]
    fn root_bound_is_fujiwaras() {
        let mut next = crate::geometry::uniform_stream(9);
        for _ in 0..5000 {
            let len = 3 + (next() * 6.0) as usize;
            let p: Vec<f64> = (0..len)
                .map(|_| (2.0 * next() - 1.0) * 10f64.powf(6.0 * next() - 3.0))
                .collect();
            let n = len - 1;
            let full = (1..=n)
                .map(|k| {
                    let ratio = (p[k] / p[0]).abs();
                    if k == n {
                        (ratio * 0.5).powf(1.0 / n as f64)
                    } else {
                        ratio.powf(1.0 / k as f64)
                    }
                })
                .fold(0.0, f64::max);
            let want = 2.0 * full * (1.0 + 1e-9) + 1e-300;
            let got = root_bound(&p);
            assert!(
                (got - want).abs() <= 1e-14 * want,
                "{got} vs {want} for {p:?}"
            );
        }
    }

    #[test]
    fn stable_quadratic() {
        let r = quadratic(1.0, -1e8, 1.0);
        assert!((r.values[0] - 1e-8).abs() < 1e-20);
    }
}
