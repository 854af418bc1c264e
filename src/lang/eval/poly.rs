//! `poly { n, <...> }`, `cubic { <...> }`, `polynomial { n, xyz(i, j, k): c ... }` and
//! `julia_fractal { ... }`: the algebraic and fractal surfaces.

use super::super::diagnostics::{Diagnostic, Span};
use super::super::syntax::{Punct, Token};
use super::Evaluator;
use super::value::{ObjectValue, Value};
use crate::geometry::{POLY_MAX_ORDER, poly_term_count};
use crate::scene::{JuliaAlgebra, JuliaFractal, JuliaFunction, Object, Shape};

type R<T> = Result<T, Diagnostic>;

fn shape(s: Shape) -> ObjectValue {
    ObjectValue {
        object: Some(Object::new(s)),
        ..ObjectValue::default()
    }
}

fn poly(order: usize, coefficients: Vec<f64>) -> ObjectValue {
    shape(Shape::Poly {
        order: order as u8,
        coefficients,
    })
}

/// The position of the exponents (i, j, k) in POV-Ray's coefficient list for `order`:
/// the terms of higher x powers come first, and within them those of higher y powers.
fn term_index(order: usize, (i, j, k): (usize, usize, usize)) -> usize {
    // Terms with x power above i: all terms of total order n - i' for i' > i, counted as
    // the triangular numbers of the orders below.
    let tri = |m: usize| (m + 1) * (m + 2) / 2;
    let before_x: usize = ((i + 1)..=order).map(|ii| tri(order - ii)).sum();
    let rest = order - i;
    let before_y: usize = ((j + 1)..=rest).map(|jj| rest - jj + 1).sum();
    before_x + before_y + (rest - j - k)
}

impl Evaluator<'_> {
    /// `poly { order, <coefficients> }`, order 2 to 7.
    pub(super) fn poly_items(&mut self) -> R<ObjectValue> {
        let order = self.poly_order()?;
        self.eat(Punct::Comma)?;
        let coefficients = self.coefficient_list(order, "poly")?;
        Ok(poly(order, coefficients))
    }

    /// `cubic { <20 coefficients> }`: `poly` of order 3.
    pub(super) fn cubic_items(&mut self) -> R<ObjectValue> {
        let coefficients = self.coefficient_list(3, "cubic")?;
        Ok(poly(3, coefficients))
    }

    /// `polynomial { order, xyz(i, j, k): c, ... }`: the terms by their exponents, the
    /// others zero; a term given twice keeps the last value.
    pub(super) fn polynomial_items(&mut self) -> R<ObjectValue> {
        let order = self.poly_order()?;
        self.eat(Punct::Comma)?;
        let mut coefficients = vec![0.0; poly_term_count(order)];
        while self.peek()?.ident() == Some("xyz") {
            let kw = self.next()?;
            self.expect(Punct::LParen, "after `xyz`")?;
            let mut e = [0usize; 3];
            let mut span = kw.span;
            for (n, slot) in e.iter_mut().enumerate() {
                if n > 0 {
                    self.expect(Punct::Comma, "between the powers of `xyz(i, j, k)`")?;
                }
                let (v, s) = self.expr()?;
                *slot = self.power(&v, s)?;
                span = span.join(s);
            }
            let close = self.expect(Punct::RParen, "to close `xyz(`")?;
            span = span.join(close.span);
            if e.iter().sum::<usize>() > order {
                return Err(self.err(
                    span,
                    format!(
                        "the term xyz({}, {}, {}) is of a higher order than the polynomial's {order}",
                        e[0], e[1], e[2]
                    ),
                ));
            }
            self.expect(Punct::Colon, "after `xyz(i, j, k)`")?;
            let c = self.float()?;
            coefficients[term_index(order, (e[0], e[1], e[2]))] = c;
            self.eat(Punct::Comma)?;
        }
        Ok(poly(order, coefficients))
    }

    /// A polynomial's order: a whole number from 2 to 7.
    fn poly_order(&mut self) -> R<usize> {
        let (v, s) = self.expr()?;
        let f = self.to_float(&v, s)?;
        if f.fract() != 0.0 || !(2.0..=POLY_MAX_ORDER as f64).contains(&f) {
            return Err(self.err(
                s,
                format!("a polynomial's order must be a whole number from 2 to 7, found {f}"),
            ));
        }
        Ok(f as usize)
    }

    fn power(&self, v: &Value, s: Span) -> R<usize> {
        let f = self.to_float(v, s)?;
        if f.fract() != 0.0 || f < 0.0 {
            return Err(self.err(s, format!("a power must be a whole number >= 0, found {f}")));
        }
        Ok(f as usize)
    }

    /// `<c0, c1, ...>` with exactly as many coefficients as the order has terms.
    fn coefficient_list(&mut self, order: usize, what: &str) -> R<Vec<f64>> {
        let want = poly_term_count(order);
        let open = self.expect(
            Punct::Lt,
            &format!("to open the {what}'s {want} coefficients"),
        )?;
        let mut coefficients = Vec::with_capacity(want);
        let mut span = open.span;
        loop {
            let (v, s) = self.additive()?;
            coefficients.push(self.to_float(&v, s)?);
            span = span.join(s);
            if !self.eat(Punct::Comma)? {
                break;
            }
        }
        let close = self.expect(Punct::Gt, &format!("after the {what}'s coefficients"))?;
        if coefficients.len() != want {
            return Err(self.err(
                span.join(close.span),
                format!(
                    "a {what} of order {order} takes {want} coefficients, found {}",
                    coefficients.len()
                ),
            ));
        }
        Ok(coefficients)
    }

    /// `julia_fractal { <c> [quaternion | hypercomplex] [function] max_iteration n
    /// precision p slice <n>, d }`, up to the object modifiers.
    pub(super) fn julia_items(&mut self) -> R<ObjectValue> {
        let (v, s) = self.expr()?;
        let mut j = JuliaFractal {
            c: self.vector4(&v, s, "the julia parameter")?,
            ..JuliaFractal::default()
        };
        loop {
            let tok = self.peek()?;
            let Some(word) = tok.ident() else { break };
            if !self.julia_item(&mut j, &tok, word)? {
                break;
            }
        }
        if j.algebra == JuliaAlgebra::Quaternion
            && !matches!(j.function, JuliaFunction::Sqr | JuliaFunction::Cube)
        {
            let tok = self.peek()?;
            return Err(self.err(
                tok.span,
                "a quaternion julia_fractal takes only `sqr` or `cube`",
            ));
        }
        Ok(shape(Shape::Julia(Box::new(j))))
    }

    /// One of the fractal's own items; false (nothing read) for other words.
    fn julia_item(&mut self, j: &mut JuliaFractal, tok: &Token, word: &str) -> R<bool> {
        let function = match word {
            "sqr" => Some(JuliaFunction::Sqr),
            "cube" => Some(JuliaFunction::Cube),
            "exp" => Some(JuliaFunction::Exp),
            "reciprocal" => Some(JuliaFunction::Reciprocal),
            "sin" => Some(JuliaFunction::Sin),
            "cos" => Some(JuliaFunction::Cos),
            "sinh" => Some(JuliaFunction::Sinh),
            "cosh" => Some(JuliaFunction::Cosh),
            "ln" => Some(JuliaFunction::Ln),
            _ => None,
        };
        if let Some(f) = function {
            self.next()?;
            j.function = f;
            return Ok(true);
        }
        match word {
            "quaternion" => j.algebra = JuliaAlgebra::Quaternion,
            "hypercomplex" => j.algebra = JuliaAlgebra::Hypercomplex,
            "max_iteration" => {
                self.next()?;
                let n = self.float()?;
                j.max_iteration = n.clamp(1.0, 1e6) as u32;
                return Ok(true);
            }
            "precision" => {
                self.next()?;
                let (v, s) = self.expr()?;
                let p = self.to_float(&v, s)?;
                if !(p > 0.0 && p.is_finite()) {
                    return Err(self.err(s, format!("precision must be positive, found {p}")));
                }
                j.precision = p;
                return Ok(true);
            }
            "slice" => {
                self.next()?;
                let (v, s) = self.expr()?;
                j.slice = self.vector4(&v, s, "the slice normal")?;
                self.eat(Punct::Comma)?;
                j.distance = self.float()?;
                return Ok(true);
            }
            "pwr" => {
                self.next()?;
                self.expect(Punct::LParen, "after `pwr`")?;
                let x = self.float()?;
                self.expect(Punct::Comma, "between the two parts of `pwr(x, y)`")?;
                let y = self.float()?;
                self.expect(Punct::RParen, "to close `pwr(`")?;
                j.function = JuliaFunction::Pwr(x, y);
                return Ok(true);
            }
            "asin" | "acos" | "tan" | "atan" | "asinh" | "acosh" | "tanh" | "atanh" => {
                return Err(self.err(
                    tok.span,
                    format!(
                        "unsupported: the julia_fractal function `{word}` is not supported yet"
                    ),
                ));
            }
            _ => return Ok(false),
        }
        self.next()?;
        Ok(true)
    }

    /// A 4-D vector: POV-Ray pads shorter ones with zeros.
    fn vector4(&self, v: &Value, s: Span, what: &str) -> R<[f64; 4]> {
        match v {
            Value::Vector(vec) => Ok([vec.c[0], vec.c[1], vec.c[2], vec.c[3]]),
            Value::Float(f) => Ok([*f; 4]),
            other => Err(self.err(
                s,
                format!("{what} must be a 4-D vector, found {}", other.kind_name()),
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::term_index;
    use crate::geometry::poly_term_count;

    #[test]
    fn term_index_follows_povrays_order() {
        for order in 2..=7 {
            let mut n = 0;
            for i in (0..=order).rev() {
                for j in (0..=order - i).rev() {
                    for k in (0..=order - i - j).rev() {
                        assert_eq!(term_index(order, (i, j, k)), n, "{order}: {i} {j} {k}");
                        n += 1;
                    }
                }
            }
            assert_eq!(n, poly_term_count(order));
        }
    }
}
