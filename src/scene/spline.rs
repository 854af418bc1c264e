//! The 2-D splines of `prism` (closed sub-shapes) and `lathe` (one open curve), as POV-Ray
//! forms them from the points, turned into one cubic polynomial per segment.
//!
//! Measured with povray (an orthographic view of each spline kind, matched pixel for pixel
//! against the candidate curves):
//! - linear: straight segments between consecutive points;
//! - quadratic: the segment from B to C after A has B's tangent (C - A) / 2;
//! - cubic: Catmull-Rom, the segment from B to C between A and D has tangents (C - A) / 2
//!   at B and (D - B) / 2 at C;
//! - bezier: groups of four points, the cubic Bezier curve of each group.

use glam::DVec2;

/// How the points of a prism or lathe make curves.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum SplineKind {
    #[default]
    Linear,
    Quadratic,
    Cubic,
    Bezier,
}

impl SplineKind {
    pub fn keyword(self) -> &'static str {
        match self {
            SplineKind::Linear => "linear_spline",
            SplineKind::Quadratic => "quadratic_spline",
            SplineKind::Cubic => "cubic_spline",
            SplineKind::Bezier => "bezier_spline",
        }
    }
}

/// One segment: P(s) = c[0] + c[1] s + c[2] s^2 + c[3] s^3 for s in [0, 1].
pub type Segment = [DVec2; 4];

pub fn evaluate(c: &Segment, s: f64) -> DVec2 {
    c[0] + (c[1] + (c[2] + c[3] * s) * s) * s
}

pub fn tangent(c: &Segment, s: f64) -> DVec2 {
    c[1] + (c[2] * 2.0 + c[3] * (3.0 * s)) * s
}

fn linear(a: DVec2, b: DVec2) -> Segment {
    [a, b - a, DVec2::ZERO, DVec2::ZERO]
}

fn quadratic(a: DVec2, b: DVec2, c: DVec2) -> Segment {
    [b, (c - a) * 0.5, (a + c) * 0.5 - b, DVec2::ZERO]
}

fn cubic(p: &[DVec2]) -> Segment {
    let (a, b, c, d) = (p[0], p[1], p[2], p[3]);
    [
        b,
        (c - a) * 0.5,
        a - b * 2.5 + c * 2.0 - d * 0.5,
        (-a + b * 3.0 - c * 3.0 + d) * 0.5,
    ]
}

fn bezier(p: &[DVec2]) -> Segment {
    let (a, b, c, d) = (p[0], p[1], p[2], p[3]);
    [
        a,
        (b - a) * 3.0,
        (a - b * 2.0 + c) * 3.0,
        -a + b * 3.0 - c * 3.0 + d,
    ]
}

/// A prism's segments.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct PrismProfile {
    pub segments: Vec<Segment>,
    /// A linear spline whose last sub-polygon did not return to its first point was closed
    /// (POV-Ray warns and closes it).
    pub closed_for_you: bool,
}

/// A prism's closed sub-shapes, by POV-Ray's rules:
/// - linear: a sub-polygon ends at the point that repeats its first;
/// - quadratic: a control point, then the curve from the next point to the point that
///   repeats it;
/// - cubic: the same, and one more control point after the repeat;
/// - bezier: groups of four points; a sub-shape ends with the group whose last point
///   repeats the sub-shape's first.
///
/// The error says what is wrong with the points.
pub fn prism_profile(kind: SplineKind, p: &[DVec2]) -> Result<PrismProfile, String> {
    let mut out = PrismProfile::default();
    let n = p.len();
    let mut start = 0;
    while start < n {
        match kind {
            SplineKind::Linear => {
                let end = (start + 1..n).find(|&j| p[j] == p[start]);
                let end = end.unwrap_or_else(|| {
                    out.closed_for_you = true;
                    n
                });
                for i in start..end {
                    let next = if i + 1 < end { p[i + 1] } else { p[start] };
                    out.segments.push(linear(p[i], next));
                }
                start = end + 1;
            }
            SplineKind::Quadratic | SplineKind::Cubic => {
                let cubic_kind = kind == SplineKind::Cubic;
                let first = start + 1;
                let end = (first + 1..n).find(|&j| first < n && p[j] == p[first]);
                let need = if cubic_kind { "a cubic" } else { "a quadratic" };
                let Some(end) = end else {
                    return Err(format!(
                        "{need} spline prism's sub-shape starting at point {} does not close: \
                         the point after its control point must come back",
                        start + 1
                    ));
                };
                if cubic_kind && end + 1 >= n {
                    return Err(format!(
                        "a cubic spline prism needs a control point after point {}, which \
                         closes its sub-shape",
                        end + 1
                    ));
                }
                for i in first..end {
                    out.segments.push(if cubic_kind {
                        cubic(&p[i - 1..i + 3])
                    } else {
                        quadratic(p[i - 1], p[i], p[i + 1])
                    });
                }
                start = end + 1 + usize::from(cubic_kind);
            }
            SplineKind::Bezier => {
                if !n.is_multiple_of(4) {
                    return Err(format!(
                        "a bezier spline prism needs groups of four points, found {n}"
                    ));
                }
                let mut g = start;
                loop {
                    if g >= n {
                        return Err(format!(
                            "the bezier spline prism's sub-shape starting at point {} does \
                             not close: no group ends on its first point",
                            start + 1
                        ));
                    }
                    out.segments.push(bezier(&p[g..g + 4]));
                    g += 4;
                    if p[g - 1] == p[start] {
                        break;
                    }
                }
                start = g;
            }
        }
    }
    if out.segments.len() < 2 && kind == SplineKind::Linear || out.segments.is_empty() {
        return Err("the prism's points make no closed shape".to_string());
    }
    Ok(out)
}

/// A lathe's curve: consecutive segments through the points (quadratic and cubic splines
/// take a control point before, cubic one after; bezier groups of four).
pub fn lathe_profile(kind: SplineKind, p: &[DVec2]) -> Result<Vec<Segment>, String> {
    let n = p.len();
    let (least, what) = match kind {
        SplineKind::Linear => (2, "two"),
        SplineKind::Quadratic => (3, "three"),
        SplineKind::Cubic => (4, "four"),
        SplineKind::Bezier => (4, "four"),
    };
    if n < least {
        return Err(format!(
            "a {} lathe needs at least {what} points, found {n}",
            kind.keyword()
        ));
    }
    Ok(match kind {
        SplineKind::Linear => p.windows(2).map(|w| linear(w[0], w[1])).collect(),
        SplineKind::Quadratic => p.windows(3).map(|w| quadratic(w[0], w[1], w[2])).collect(),
        SplineKind::Cubic => p.windows(4).map(cubic).collect(),
        SplineKind::Bezier => {
            if !n.is_multiple_of(4) {
                return Err(format!(
                    "a bezier_spline lathe needs groups of four points, found {n}"
                ));
            }
            p.chunks(4).map(bezier).collect()
        }
    })
}

/// One piece of a surface of revolution: r^2 = k[0] + k[1] u + k[2] u^2 + k[3] u^3 with
/// u = y - h0, for y in [h0, h1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SorSegment {
    pub h0: f64,
    pub h1: f64,
    pub k: [f64; 4],
}

impl SorSegment {
    /// r^2 at height y.
    pub fn radius_squared(&self, y: f64) -> f64 {
        let u = y - self.h0;
        self.k[0] + (self.k[1] + (self.k[2] + self.k[3] * u) * u) * u
    }

    /// d(r^2)/dy at height y.
    pub fn slope(&self, y: f64) -> f64 {
        let u = y - self.h0;
        self.k[1] + (2.0 * self.k[2] + 3.0 * self.k[3] * u) * u
    }
}

/// A `sor`'s pieces, points <r, h>: r^2 is a cubic of h between consecutive points from
/// the second to the last but one, through their r^2, with slope 2 r dr/dh at each point,
/// dr/dh taken from its two neighbours (measured with povray: an orthographic silhouette
/// matched to half a pixel, where slopes from the neighbours' r^2 missed by six pixels).
/// The heights must increase (a control point may share its neighbour's).
pub fn sor_profile(p: &[DVec2]) -> Result<Vec<SorSegment>, String> {
    let n = p.len();
    if n < 4 {
        return Err(format!("a sor needs at least four points, found {n}"));
    }
    // As povray: no height may fall, and the heights the curve joins must rise (the
    // control points may repeat their neighbours' heights).
    let falls = |i: usize| p[i].y < p[i - 1].y || (i > 1 && i < n - 1 && p[i].y == p[i - 1].y);
    if let Some(i) = (1..n).find(|&i| falls(i)) {
        return Err(format!(
            "the sor's heights must increase, but point {} is at {} after {}",
            i + 1,
            p[i].y,
            p[i - 1].y
        ));
    }
    let slope = |i: usize| 2.0 * p[i].x * (p[i + 1].x - p[i - 1].x) / (p[i + 1].y - p[i - 1].y);
    Ok((1..n - 2)
        .map(|i| {
            let (h0, h1) = (p[i].y, p[i + 1].y);
            let h = h1 - h0;
            let (b0, b1) = (p[i].x * p[i].x, p[i + 1].x * p[i + 1].x);
            let (m0, m1) = (slope(i), slope(i + 1));
            let delta = (b1 - b0) / h;
            SorSegment {
                h0,
                h1,
                k: [
                    b0,
                    m0,
                    (3.0 * delta - 2.0 * m0 - m1) / h,
                    (m0 + m1 - 2.0 * delta) / (h * h),
                ],
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn segments_pass_through_their_points() {
        let p = [v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)];
        let q = quadratic(p[0], p[1], p[2]);
        assert_eq!(evaluate(&q, 0.0), p[1]);
        assert!((evaluate(&q, 1.0) - p[2]).length() < 1e-15);
        assert_eq!(tangent(&q, 0.0), (p[2] - p[0]) * 0.5);
        let c = cubic(&p);
        assert!((evaluate(&c, 1.0) - p[2]).length() < 1e-15);
        assert!((tangent(&c, 1.0) - (p[3] - p[1]) * 0.5).length() < 1e-15);
        let b = bezier(&p);
        assert!((evaluate(&b, 1.0) - p[3]).length() < 1e-15);
        assert_eq!(tangent(&b, 0.0), (p[1] - p[0]) * 3.0);
    }

    #[test]
    fn sor_pieces_join_with_the_measured_slopes() {
        let p = [
            v(0.2, -0.3),
            v(0.5, 0.1),
            v(0.9, 0.6),
            v(0.3, 1.2),
            v(0.6, 1.8),
        ];
        let s = sor_profile(&p).unwrap();
        assert_eq!(s.len(), 2);
        assert!((s[0].radius_squared(0.1) - 0.25).abs() < 1e-12);
        assert!((s[0].radius_squared(0.6) - 0.81).abs() < 1e-12);
        assert!((s[1].radius_squared(1.2) - 0.09).abs() < 1e-12);
        let m = 2.0 * 0.9 * (0.3 - 0.5) / (1.2 - 0.1);
        assert!((s[0].slope(0.6) - m).abs() < 1e-12 && (s[1].slope(0.6) - m).abs() < 1e-12);
        assert!(sor_profile(&p[..3]).is_err());
        assert!(sor_profile(&[v(1.0, 0.0), v(1.0, 1.0), v(1.0, 1.0), v(1.0, 2.0)]).is_err());
        assert!(sor_profile(&[v(1.0, 1.0), v(1.0, 0.0), v(1.0, 1.0), v(1.0, 2.0)]).is_err());
        // povray's sor1.pov: the first control point at the height of the second.
        assert!(sor_profile(&[v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(1.0, 2.0)]).is_ok());
    }

    #[test]
    fn prism_sub_shapes() {
        // Two squares, linear: 10 points, 8 segments.
        let sq = |o: f64, s: f64| [v(o, o), v(o + s, o), v(o + s, o + s), v(o, o + s), v(o, o)];
        let pts: Vec<DVec2> = sq(0.0, 4.0).into_iter().chain(sq(1.0, 2.0)).collect();
        let r = prism_profile(SplineKind::Linear, &pts).unwrap();
        assert_eq!((r.segments.len(), r.closed_for_you), (8, false));
        // Left open: closed with a note.
        let r = prism_profile(SplineKind::Linear, &pts[..4]).unwrap();
        assert_eq!((r.segments.len(), r.closed_for_you), (4, true));
        // Quadratic: control, 4 points, the repeat.
        let q = [
            v(0.0, 1.0),
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(1.0, 1.0),
            v(0.0, 1.0),
            v(0.0, 0.0),
        ];
        assert_eq!(
            prism_profile(SplineKind::Quadratic, &q)
                .unwrap()
                .segments
                .len(),
            4
        );
        assert!(prism_profile(SplineKind::Quadratic, &q[..5]).is_err());
        // Cubic: one more control point.
        let mut c = q.to_vec();
        c.push(v(1.0, 0.0));
        assert_eq!(
            prism_profile(SplineKind::Cubic, &c).unwrap().segments.len(),
            4
        );
        assert!(prism_profile(SplineKind::Cubic, &q).is_err());
        // Bezier: two groups making a lens.
        let b = [v(0.0, 0.0), v(0.3, 1.0), v(0.7, 1.0), v(1.0, 0.0)];
        let b2 = [v(1.0, 0.0), v(0.7, -1.0), v(0.3, -1.0), v(0.0, 0.0)];
        let both: Vec<DVec2> = b.into_iter().chain(b2).collect();
        assert_eq!(
            prism_profile(SplineKind::Bezier, &both)
                .unwrap()
                .segments
                .len(),
            2
        );
        assert!(prism_profile(SplineKind::Bezier, &b).is_err());
        assert!(prism_profile(SplineKind::Bezier, &both[..6]).is_err());
    }
}
