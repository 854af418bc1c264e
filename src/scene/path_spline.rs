//! The language's `spline { ... }`: vectors at times, read at any time (`S(t)`), as scenes
//! move cameras and objects along paths. Each kind's rule was fitted to the values
//! POV-Ray 3.7 prints for the same splines (tests below):
//! - entries are sorted by time; of two at the same time the first stays;
//! - linear: straight between neighbours;
//! - quadratic: the segment from t_i to t_(i+1) is the parabola through entries i-1, i, i+1
//!   (0, 1, 2 for the first segment), so two entries give a straight line;
//! - cubic: Hermite segments whose tangent at each entry is the mean of the slopes of its
//!   two neighbouring chords; only between the second and the second-to-last entries (the
//!   first and last steer the ends), so three entries or fewer give the second entry;
//! - natural: the natural cubic spline through every entry (no curvature at the ends);
//! - outside the range a spline covers, it gives the entry at the nearer end.

/// How a spline passes through its entries.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum PathKind {
    #[default]
    Linear,
    Quadratic,
    Cubic,
    Natural,
}

impl PathKind {
    pub fn named(keyword: &str) -> Option<PathKind> {
        Some(match keyword {
            "linear_spline" => PathKind::Linear,
            "quadratic_spline" => PathKind::Quadratic,
            "cubic_spline" => PathKind::Cubic,
            "natural_spline" => PathKind::Natural,
            _ => return None,
        })
    }
}

/// A value of up to five components, as the language's vectors are.
pub type PathValue = [f64; 5];

#[derive(Clone, Debug, PartialEq, Default)]
pub struct PathSpline {
    pub kind: PathKind,
    /// Sorted by time, times distinct.
    entries: Vec<(f64, PathValue)>,
    /// Components of the widest entry (the value has as many).
    pub width: u8,
    /// The natural spline's second derivatives at the entries, per component: solved
    /// once by [`PathSpline::finish`], since functions read splines per shading point.
    second: Vec<PathValue>,
}

impl PathSpline {
    /// Adds an entry in time order; an entry at a time already present is ignored, as
    /// POV-Ray ignores it.
    pub fn insert(&mut self, t: f64, v: PathValue, width: u8) {
        let at = self.entries.partition_point(|(s, _)| *s < t);
        if self.entries.get(at).is_some_and(|(s, _)| *s == t) {
            return;
        }
        self.entries.insert(at, (t, v));
        self.width = self.width.max(width);
        self.second.clear();
    }

    /// Readies the spline for reading once its entries are in.
    pub fn finish(&mut self) {
        let columns: Vec<Vec<f64>> = (0..5).map(|c| self.second_derivatives(c)).collect();
        self.second = (0..self.entries.len())
            .map(|i| std::array::from_fn(|c| columns[c][i]))
            .collect();
    }

    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The value at `t`, with the spline's own kind or another (`S(t, linear_spline)`).
    pub fn at(&self, t: f64, kind: Option<PathKind>) -> PathValue {
        let e = &self.entries;
        match (e.len(), kind.unwrap_or(self.kind)) {
            (0, _) => [0.0; 5],
            (1, _) => e[0].1,
            (_, PathKind::Linear) => self.linear(t),
            (_, PathKind::Quadratic) => self.quadratic(t),
            (_, PathKind::Cubic) => self.cubic(t),
            (_, PathKind::Natural) => self.natural(t),
        }
    }

    /// The segment holding `t` within entries `first..=last`, or the end entry's value
    /// outside them.
    fn segment(&self, t: f64, first: usize, last: usize) -> Result<usize, PathValue> {
        let e = &self.entries;
        if t <= e[first].0 || first >= last {
            return Err(e[first].1);
        }
        if t >= e[last].0 {
            return Err(e[last].1);
        }
        let i = e.partition_point(|(s, _)| *s <= t) - 1;
        Ok(i.clamp(first, last - 1))
    }

    fn linear(&self, t: f64) -> PathValue {
        let i = match self.segment(t, 0, self.entries.len() - 1) {
            Ok(i) => i,
            Err(v) => return v,
        };
        let ((t0, a), (t1, b)) = (self.entries[i], self.entries[i + 1]);
        let s = (t - t0) / (t1 - t0);
        std::array::from_fn(|c| a[c] + (b[c] - a[c]) * s)
    }

    fn quadratic(&self, t: f64) -> PathValue {
        let n = self.entries.len();
        let i = match self.segment(t, 0, n - 1) {
            Ok(i) => i,
            Err(v) => return v,
        };
        if n == 2 {
            return self.linear(t);
        }
        let j = i.saturating_sub(1).min(n - 3);
        let [(t0, a), (t1, b), (t2, c)] = [0, 1, 2].map(|k| self.entries[j + k]);
        let l0 = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
        let l1 = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
        let l2 = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
        std::array::from_fn(|k| a[k] * l0 + b[k] * l1 + c[k] * l2)
    }

    /// The mean of the slopes of the chords on either side of entry i.
    fn tangent(&self, i: usize) -> PathValue {
        let e = &self.entries;
        let slope = |a: usize, b: usize, c: usize| (e[b].1[c] - e[a].1[c]) / (e[b].0 - e[a].0);
        std::array::from_fn(|c| 0.5 * (slope(i - 1, i, c) + slope(i, i + 1, c)))
    }

    fn cubic(&self, t: f64) -> PathValue {
        let n = self.entries.len();
        if n < 4 {
            return self.entries[1.min(n - 1)].1;
        }
        let i = match self.segment(t, 1, n - 2) {
            Ok(i) => i,
            Err(v) => return v,
        };
        let ((t0, a), (t1, b)) = (self.entries[i], self.entries[i + 1]);
        let (ma, mb) = (self.tangent(i), self.tangent(i + 1));
        let h = t1 - t0;
        let s = (t - t0) / h;
        let (s2, s3) = (s * s, s * s * s);
        let (h00, h10, h01, h11) = (
            2.0 * s3 - 3.0 * s2 + 1.0,
            s3 - 2.0 * s2 + s,
            3.0 * s2 - 2.0 * s3,
            s3 - s2,
        );
        std::array::from_fn(|c| h00 * a[c] + h10 * h * ma[c] + h01 * b[c] + h11 * h * mb[c])
    }

    fn natural(&self, t: f64) -> PathValue {
        let n = self.entries.len();
        let i = match self.segment(t, 0, n - 1) {
            Ok(i) => i,
            Err(v) => return v,
        };
        debug_assert_eq!(self.second.len(), n, "read before `finish`");
        let ((t0, a), (t1, b)) = (self.entries[i], self.entries[i + 1]);
        let (m0, m1) = match (self.second.get(i), self.second.get(i + 1)) {
            (Some(m0), Some(m1)) => (*m0, *m1),
            _ => ([0.0; 5], [0.0; 5]),
        };
        let h = t1 - t0;
        let (u, w) = ((t1 - t) / h, (t - t0) / h);
        std::array::from_fn(|c| {
            u * a[c] + w * b[c] + ((u * u * u - u) * m0[c] + (w * w * w - w) * m1[c]) * h * h / 6.0
        })
    }

    /// Component c's second derivatives at the entries of the natural spline (0 at both
    /// ends): the tridiagonal system solved by elimination.
    fn second_derivatives(&self, c: usize) -> Vec<f64> {
        let e = &self.entries;
        let n = e.len();
        let mut m = vec![0.0; n];
        if n < 3 {
            return m;
        }
        let h = |i: usize| e[i + 1].0 - e[i].0;
        let slope = |i: usize| (e[i + 1].1[c] - e[i].1[c]) / h(i);
        // Forward elimination over rows 1..n-1: diag' and rhs'.
        let mut diag = vec![0.0; n];
        let mut rhs = vec![0.0; n];
        for i in 1..n - 1 {
            let (lower, upper) = (h(i - 1), h(i));
            diag[i] = 2.0 * (lower + upper);
            rhs[i] = 6.0 * (slope(i) - slope(i - 1));
            if i > 1 {
                let f = lower / diag[i - 1];
                diag[i] -= f * h(i - 1);
                rhs[i] -= f * rhs[i - 1];
            }
        }
        for i in (1..n - 1).rev() {
            let next = if i + 1 < n - 1 { h(i) * m[i + 1] } else { 0.0 };
            m[i] = (rhs[i] - next) / diag[i];
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spline(kind: PathKind, entries: &[(f64, [f64; 3])]) -> PathSpline {
        let mut s = PathSpline {
            kind,
            ..PathSpline::default()
        };
        for (t, v) in entries {
            s.insert(*t, [v[0], v[1], v[2], 0.0, 0.0], 3);
        }
        s.finish();
        s
    }

    /// The five entries POV-Ray printed values for (tests/lang/expressions/splines.pov).
    const FIVE: [(f64, [f64; 3]); 5] = [
        (0.0, [0.0, 0.0, 0.0]),
        (1.0, [1.0, 2.0, 0.0]),
        (2.5, [3.0, 1.0, 1.0]),
        (3.0, [4.0, 4.0, -1.0]),
        (5.0, [6.0, 0.0, 2.0]),
    ];

    fn close(kind: PathKind, t: f64, want: [f64; 3]) {
        let got = spline(kind, &FIVE).at(t, None);
        for c in 0..3 {
            assert!(
                (got[c] - want[c]).abs() < 5e-9,
                "{kind:?} at {t}: {got:?} vs {want:?}"
            );
        }
    }

    #[test]
    fn each_kind_gives_povrays_values() {
        use PathKind::*;
        close(Linear, 1.25, [1.333333333, 1.833333333, 0.166666667]);
        close(Linear, 4.5, [5.5, 1.0, 1.25]);
        close(Linear, -1.0, [0.0, 0.0, 0.0]);
        close(Quadratic, 0.25, [0.225, 0.7, -0.05]);
        close(Quadratic, 1.25, [1.291666667, 2.166666667, 0.083333333]);
        close(Quadratic, 2.75, [3.479166667, 2.291666667, 0.145833333]);
        close(Quadratic, 4.0, [5.4, 5.2, -1.7]);
        close(Quadratic, 6.0, [6.0, 0.0, 2.0]);
        close(Cubic, 0.5, [1.0, 2.0, 0.0]);
        close(Cubic, 1.25, [1.292824074, 1.949074074, 0.189814815]);
        close(Cubic, 2.25, [2.603009259, 0.634259259, 1.226851852]);
        close(Cubic, 2.75, [3.510416667, 2.541666667, -0.026041667]);
        close(Cubic, 4.0, [4.0, 4.0, -1.0]);
        close(Natural, 0.25, [0.247767857, 0.791071429, -0.140066964]);
        close(Natural, 1.75, [1.83125, 0.555, 1.3015625]);
        close(Natural, 3.25, [4.4296875, 5.00625, -1.654296875]);
        close(Natural, 4.25, [5.532366071, 3.866964286, -0.742466518]);
        close(Natural, -0.25, [0.0, 0.0, 0.0]);
    }

    #[test]
    fn order_duplicates_and_short_splines_as_povray() {
        use PathKind::*;
        // Entries sorted; a second entry at the same time is ignored.
        let u = spline(
            Linear,
            &[
                (2.0, [2.0, 0.0, 0.0]),
                (0.0, [0.0; 3]),
                (1.0, [1.0, 5.0, 0.0]),
            ],
        );
        assert_eq!(u.at(0.5, None)[..3], [0.5, 2.5, 0.0]);
        let d = spline(
            Linear,
            &[
                (0.0, [0.0; 3]),
                (1.0, [1.0; 3]),
                (1.0, [5.0; 3]),
                (2.0, [2.0; 3]),
            ],
        );
        assert_eq!(d.at(1.5, None)[..3], [1.5; 3]);
        // Three entries: a cubic is its second entry everywhere, a quadratic of two is
        // straight, a natural spline of three bends.
        let three = [
            (0.0, [0.0; 3]),
            (1.0, [1.0, 1.0, 0.0]),
            (3.0, [0.0, 2.0, 2.0]),
        ];
        assert_eq!(spline(Cubic, &three).at(0.5, None)[..3], [1.0, 1.0, 0.0]);
        assert_eq!(
            spline(Quadratic, &three[..2]).at(0.5, None)[..3],
            [0.5, 0.5, 0.0]
        );
        let n3 = spline(Natural, &three);
        for (t, want) in [
            (0.5, [0.59375, 0.53125, -0.0625]),
            (2.5, [0.484375, 1.828125, 1.34375]),
        ] {
            let got = n3.at(t, None);
            assert!((0..3).all(|c| (got[c] - want[c]).abs() < 1e-12), "{got:?}");
        }
        // Cubic of five, and another kind asked at the call.
        let five = [
            (0.0, [0.0; 3]),
            (1.0, [1.0, 1.0, 0.0]),
            (2.0, [4.0, 0.0, 0.0]),
            (3.0, [0.0, 3.0, 0.0]),
            (4.0, [1.0; 3]),
        ];
        let c5 = spline(Cubic, &five);
        assert_eq!(c5.at(1.5, None)[..3], [2.8125, 0.375, 0.0]);
        assert_eq!(c5.at(2.5, None)[..3], [2.125, 1.5625, -0.0625]);
        assert_eq!(
            spline(Cubic, &FIVE).at(1.5, Some(Linear))[0],
            1.0 + 2.0 / 3.0
        );
    }
}
