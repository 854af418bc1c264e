//! The spline shapes: `prism` (and, sharing the point lists, `lathe` and `sor`).

use glam::DVec2;

use super::super::diagnostics::{Diagnostic, Span};
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::ObjectValue;
use crate::scene::{Lathe, Object, Prism, Shape, Sor, SplineKind};

type R<T> = Result<T, Diagnostic>;

/// Words that end a point list: where a missing point shows.
const AFTER_POINTS: &[&str] = &[
    "open",
    "sturm",
    "texture",
    "pigment",
    "finish",
    "normal",
    "interior",
    "material",
    "translate",
    "rotate",
    "scale",
    "matrix",
    "transform",
    "inverse",
    "hollow",
    "no_shadow",
    "no_image",
    "no_reflection",
    "double_illuminate",
    "no_radiosity",
    "clipped_by",
    "bounded_by",
];

pub(super) fn spline_keyword(word: &str) -> Option<SplineKind> {
    Some(match word {
        "linear_spline" => SplineKind::Linear,
        "quadratic_spline" => SplineKind::Quadratic,
        "cubic_spline" => SplineKind::Cubic,
        "bezier_spline" => SplineKind::Bezier,
        _ => return None,
    })
}

impl Evaluator<'_> {
    /// `prism { [sweep] [spline] h1, h2, n, <u, v> ... }` up to the modifiers.
    pub(super) fn prism_items(&mut self, kw: &Token) -> R<ObjectValue> {
        let mut spline = SplineKind::Linear;
        let mut conic = false;
        loop {
            let tok = self.peek()?;
            match tok.ident() {
                Some("linear_sweep") => conic = false,
                Some("conic_sweep") => conic = true,
                Some(w) => match spline_keyword(w) {
                    Some(k) => spline = k,
                    None => break,
                },
                None => break,
            }
            self.next()?;
        }
        let height1 = self.float()?;
        self.eat(Punct::Comma)?;
        let height2 = self.float()?;
        self.eat(Punct::Comma)?;
        let (points, count_span) = self.point_list("prism", 3)?;
        let profile =
            crate::scene::prism_profile(spline, &points).map_err(|m| self.err(count_span, m))?;
        if profile.closed_for_you {
            self.warn(kw.span, "the linear prism is not closed; closing it");
        }
        if height1 == height2 {
            self.warn(
                kw.span,
                "the prism's two heights are equal: it has no volume",
            );
        }
        Ok(shape(Shape::Prism(Box::new(Prism {
            spline,
            conic,
            height1,
            height2,
            points,
            open: false,
        }))))
    }

    /// `sor { n, <r, h> ... }` up to the modifiers.
    pub(super) fn sor_items(&mut self) -> R<ObjectValue> {
        let (points, count_span) = self.point_list("sor", 4)?;
        crate::scene::sor_profile(&points).map_err(|m| self.err(count_span, m))?;
        Ok(shape(Shape::Sor(Sor {
            points,
            open: false,
        })))
    }

    /// `lathe { [spline] n, <r, y> ... }` up to the modifiers.
    pub(super) fn lathe_items(&mut self) -> R<ObjectValue> {
        let mut spline = SplineKind::Linear;
        while let Some(k) = self.peek()?.ident().and_then(spline_keyword) {
            spline = k;
            self.next()?;
        }
        let (points, count_span) = self.point_list("lathe", 2)?;
        crate::scene::lathe_profile(spline, &points).map_err(|m| self.err(count_span, m))?;
        Ok(shape(Shape::Lathe(Lathe { spline, points })))
    }

    /// `n, <u, v>, ...`: the count, then exactly that many 2-D points (commas optional);
    /// the span of the count for errors about the points.
    pub(super) fn point_list(&mut self, what: &str, least: usize) -> R<(Vec<DVec2>, Span)> {
        // Additive, not a full expression: in `4 <-1, 0>` the `<` opens the first point (as
        // in povray's interior/atten2.pov), it is not a comparison.
        let (v, count_span) = self.additive()?;
        let n = self.to_float(&v, count_span)?;
        if n.fract() != 0.0 || n < least as f64 || n > 1e7 {
            return Err(self.err(
                count_span,
                format!("a {what} needs a whole number of points, at least {least}, found {n}"),
            ));
        }
        let n = n as usize;
        self.count_objects(1, n * std::mem::size_of::<DVec2>(), count_span)?;
        let mut points = Vec::with_capacity(n.min(1 << 16));
        for i in 0..n {
            self.eat(Punct::Comma)?;
            let tok = self.peek()?;
            let ends = tok.is_punct(Punct::RBrace)
                || tok.ident().is_some_and(|w| AFTER_POINTS.contains(&w));
            if ends {
                return Err(self.err(
                    count_span,
                    format!("the {what} declares {n} points but gives {i}"),
                ));
            }
            let (v, s) = self.additive()?;
            let p = self.to_vec3(&v, s)?;
            points.push(DVec2::new(p.x, p.y));
        }
        self.eat(Punct::Comma)?;
        let tok = self.peek()?;
        if tok.is_punct(Punct::Lt) {
            return Err(self.err(
                tok.span,
                format!("more points than the {n} the {what} declares"),
            ));
        }
        Ok((points, count_span))
    }
}

fn shape(s: Shape) -> ObjectValue {
    ObjectValue {
        object: Some(Object::new(s)),
        lights: Vec::new(),
    }
}
