//! `spline { ... }` values and their calls `S(t)` and `S(t, cubic_spline)`: the entries
//! are read here; how a spline passes through them is src/scene/path_spline.rs.

use std::rc::Rc;

use super::super::diagnostics::Span;
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::{Value, Vector};
use crate::lang::diagnostics::Diagnostic;
use crate::scene::path_spline::{PathKind, PathSpline};

type R<T> = Result<T, Diagnostic>;

/// Most entries a spline may hold (a guard against a runaway loop filling one).
const MAX_ENTRIES: usize = 1 << 20;

impl Evaluator<'_> {
    /// `spline { [identifier] [kind] time, vector ... }`, at the keyword.
    pub(super) fn spline_value(&mut self) -> R<PathSpline> {
        let open = self.block_start("spline")?;
        let mut spline = PathSpline::default();
        loop {
            let tok = self.peek()?;
            if tok.is_punct(Punct::RBrace) {
                break;
            }
            if let Some(kind) = tok.ident().and_then(PathKind::named) {
                self.next()?;
                spline.kind = kind;
                continue;
            }
            if let Some(Value::Spline(s)) = tok.ident().and_then(|n| self.lookup(n)) {
                let copy = (**s).clone();
                self.next()?;
                spline = copy;
                continue;
            }
            self.spline_entry(&mut spline)?;
        }
        if spline.is_empty() {
            return Err(self.err(
                open.span,
                "a spline needs at least one `time, vector` entry",
            ));
        }
        self.block_end(open, "the spline")?;
        spline.finish();
        Ok(spline)
    }

    /// `time [,] vector [,]`.
    fn spline_entry(&mut self, spline: &mut PathSpline) -> R<()> {
        let t = self.float()?;
        self.eat(Punct::Comma)?;
        let (v, span) = self.expr()?;
        let (c, width) = match v {
            Value::Float(f) => ([f; 5], 1),
            Value::Vector(v) => (v.c, v.len),
            Value::Colour(c) => (c, 5),
            other => {
                return Err(self.err(
                    span,
                    format!("a spline entry is a vector, found {}", other.kind_name()),
                ));
            }
        };
        if spline.len() == MAX_ENTRIES {
            return Err(self.err(
                span,
                format!("a spline holds at most {MAX_ENTRIES} entries"),
            ));
        }
        spline.insert(t, c, width);
        self.eat(Punct::Comma)?;
        Ok(())
    }

    /// `(t [, kind])` after a spline identifier at `tok`: the vector at t.
    pub(super) fn call_spline(&mut self, tok: &Token, s: &Rc<PathSpline>) -> R<(Value, Span)> {
        self.expect(Punct::LParen, "after a spline's name: `S(t)`")?;
        let t = self.float()?;
        let mut kind = None;
        if self.eat(Punct::Comma)? {
            let k = self.next()?;
            kind = Some(k.ident().and_then(PathKind::named).ok_or_else(|| {
                self.expected(
                    "a spline kind (`linear_spline`, `quadratic_spline`, `cubic_spline`, `natural_spline`)",
                    &k,
                )
            })?);
        }
        let close = self.expect(Punct::RParen, "to close the spline's call")?;
        Ok((spline_vector(s, t, kind), tok.span.join(close.span)))
    }
}

/// A spline's value at t as the language's vector (at least two components).
pub(super) fn spline_vector(s: &PathSpline, t: f64, kind: Option<PathKind>) -> Value {
    Value::Vector(Vector {
        c: s.at(t, kind),
        len: s.width.clamp(2, 5),
    })
}
