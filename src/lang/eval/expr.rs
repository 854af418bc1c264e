//! Expressions with POV-Ray's precedence (loosest first): `? :`, `|`, `&`, comparisons,
//! `+ -`, `* /`, unary `- + !`, then `.x`-style components and `[i]` indexing.
//! Colours are 5-vectors, so `White * 0.3` and `rgb 1 * 0.5` are ordinary arithmetic.

use glam::DVec3;

use super::super::diagnostics::Span;
use super::super::syntax::{Punct, Token, TokenKind};
use super::Evaluator;
use super::compiled::Entry;
use super::functions::{self, Builtin};
use super::value::{BinOp, Value, Vector, arith, negate};
use crate::lang::diagnostics::Diagnostic;

type R<T> = Result<T, Diagnostic>;

/// Values within this of zero count as false, as in POV-Ray.
const EPSILON: f64 = 1e-10;

/// The binary operators' precedence, loosest first; all associate to the left.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Level {
    Or,
    And,
    Comparison,
    Additive,
    Multiplicative,
    /// Tighter than any binary operator: only an operand.
    Operand,
}

impl Level {
    pub(super) fn tighter(self) -> Level {
        match self {
            Level::Or => Level::And,
            Level::And => Level::Comparison,
            Level::Comparison => Level::Additive,
            Level::Additive => Level::Multiplicative,
            Level::Multiplicative | Level::Operand => Level::Operand,
        }
    }
}

impl Evaluator<'_> {
    /// A full expression of any type.
    pub(super) fn expr(&mut self) -> R<(Value, Span)> {
        if let Some(operand) = self.lone_operand() {
            return Ok(operand);
        }
        if let Some(compiled) = self.run_compiled(Entry::Expr) {
            return Ok(compiled);
        }
        let start = self.peek()?.span;
        self.enter(start)?;
        let r = self.ternary();
        self.leave();
        r
    }

    /// A lone operand: a [`plain_operand`](Self::plain_operand) followed by what cannot
    /// continue an expression (`,`, `;`, `:`, a closing bracket, `>` inside a vector, a
    /// name). Anything else (an operator next, a directive, a frame's end) takes the full
    /// descent.
    fn lone_operand(&mut self) -> Option<(Value, Span)> {
        if ends_operand(self.raw_peek(1)?, self.in_vector) {
            self.plain_operand()
        } else {
            None
        }
    }

    /// A number, or a name (not a keyword) holding a float, with no `.x`, `[i]` or `(`
    /// after it: most operands of a loop's arithmetic. Read without the descent through
    /// unary, postfix and primary, whose by-value copies of tokens and values are most of
    /// what evaluating such an operand costs (measured on issue 16's loop: 1.58 -> 1.30 s
    /// for numbers alone).
    fn plain_operand(&mut self) -> Option<(Value, Span)> {
        let tok = *self.raw_peek(0)?;
        if continues_operand(self.raw_peek(1)?) {
            return None;
        }
        let value = match tok.kind {
            TokenKind::Number(n) => n,
            TokenKind::Ident(name) if !crate::lang::parse::is_interned_keyword(name) => {
                match self.lookup(name)? {
                    Value::Float(f) => *f,
                    _ => return None,
                }
            }
            _ => return None,
        };
        self.advance();
        Some((Value::Float(value), tok.span))
    }

    pub(super) fn float(&mut self) -> R<f64> {
        let (v, span) = self.expr()?;
        self.to_float(&v, span)
    }

    /// A map entry's value: in `[0 <0, 1>]` the `<` starts the entry's vector, not a
    /// comparison, so the value stops before comparisons.
    pub(super) fn map_value(&mut self) -> R<f64> {
        let start = self.peek()?.span;
        self.enter(start)?;
        let r = self.additive();
        self.leave();
        let (v, span) = r?;
        self.to_float(&v, span)
    }

    pub(super) fn vector3(&mut self) -> R<DVec3> {
        let (v, span) = self.expr()?;
        self.to_vec3(&v, span)
    }

    pub(super) fn to_float(&self, v: &Value, span: Span) -> R<f64> {
        match v {
            Value::Float(f) => Ok(*f),
            other => Err(self.err(
                span,
                format!("expected a float, found {}", other.kind_name()),
            )),
        }
    }

    pub(super) fn to_vec3(&self, v: &Value, span: Span) -> R<DVec3> {
        match v {
            Value::Float(f) => Ok(DVec3::splat(*f)),
            Value::Vector(v) => Ok(v.xyz()),
            Value::Colour(c) => Ok(DVec3::new(c[0], c[1], c[2])),
            other => Err(self.err(
                span,
                format!("expected a vector, found {}", other.kind_name()),
            )),
        }
    }

    /// A float where a colour is expected fills r, g and b; a 4- or 5-vector also gives
    /// filter and transmit.
    pub(super) fn to_colour(&self, v: &Value, span: Span) -> R<[f64; 5]> {
        match v {
            Value::Float(f) => Ok([*f, *f, *f, 0.0, 0.0]),
            Value::Vector(v) => {
                let mut c = [0.0; 5];
                c[..v.len as usize].copy_from_slice(&v.c[..v.len as usize]);
                Ok(c)
            }
            Value::Colour(c) => Ok(*c),
            other => Err(self.err(
                span,
                format!("expected a colour, found {}", other.kind_name()),
            )),
        }
    }

    pub(super) fn truthy(&self, v: &Value, span: Span) -> R<bool> {
        Ok(is_true(self.to_float(v, span)?))
    }

    fn ternary(&mut self) -> R<(Value, Span)> {
        let (c, span) = self.binary(Level::Or)?;
        if self.eat_operator(Punct::Question)? {
            let cond = self.truthy(&c, span)?;
            let (a, sa) = self.expr()?;
            self.expect(Punct::Colon, "in `? :`")?;
            let (b, sb) = self.expr()?;
            return Ok(if cond {
                (a, span.join(sa))
            } else {
                (b, span.join(sb))
            });
        }
        Ok((c, span))
    }

    /// `+` and `-` and tighter: a map entry's value, a count before a vector.
    pub(super) fn additive(&mut self) -> R<(Value, Span)> {
        if let Some(compiled) = self.run_compiled(Entry::Additive) {
            return Ok(compiled);
        }
        self.binary(Level::Additive)
    }

    /// The binary operators from `level` up, by precedence climbing: one look at the next
    /// token per operand, where a function per level would look once per level.
    fn binary(&mut self, level: Level) -> R<(Value, Span)> {
        let (mut a, mut span) = match self.plain_operand() {
            Some(operand) => operand,
            None => self.unary()?,
        };
        loop {
            let tok = self.peek_operator()?;
            let TokenKind::Punct(p) = tok.kind else {
                break;
            };
            let Some(op_level) = self.level_of(p, &a) else {
                break;
            };
            if op_level < level {
                break;
            }
            self.next()?;
            let (b, sb) = self.binary(op_level.tighter())?;
            a = self.apply(p, (&a, span), (&b, sb), tok.span)?;
            span = span.join(sb);
        }
        Ok((a, span))
    }

    /// The level of the operator `p` after the operand `a`, or None where `p` ends the
    /// expression.
    fn level_of(&self, p: Punct, a: &Value) -> Option<Level> {
        let context = Context {
            in_vector: self.in_vector,
            grouped: self.grouping > 0,
        };
        operator_level(p, matches!(a, Value::Float(_)), context)
    }

    pub(super) fn apply(
        &self,
        p: Punct,
        (a, sa): (&Value, Span),
        (b, sb): (&Value, Span),
        at: Span,
    ) -> R<Value> {
        if let (Value::Float(x), Value::Float(y)) = (a, b) {
            return float_binary(p, *x, *y)
                .map(Value::Float)
                .ok_or_else(|| self.err(at, "division by zero"));
        }
        let truth = |t: bool| Value::Float(f64::from(u8::from(t)));
        let op = match p {
            Punct::Pipe => return Ok(truth(self.truthy(a, sa)? || self.truthy(b, sb)?)),
            Punct::Amp => return Ok(truth(self.truthy(a, sa)? && self.truthy(b, sb)?)),
            Punct::Plus => BinOp::Add,
            Punct::Minus => BinOp::Sub,
            Punct::Star => BinOp::Mul,
            Punct::Slash => BinOp::Div,
            _ => return self.compare(p, (a, sa), (b, sb)).map(truth),
        };
        arith(op, a, b).map_err(|m| self.err(at, m))
    }

    fn compare(&self, p: Punct, (a, sa): (&Value, Span), (b, sb): (&Value, Span)) -> R<bool> {
        // Strings compare in byte order, as POV-Ray 3.7 does.
        let (x, y) = match (a, b) {
            (Value::Str(a), Value::Str(b)) => match a.as_bytes().cmp(b.as_bytes()) {
                std::cmp::Ordering::Less => (0.0, 1.0),
                std::cmp::Ordering::Equal => (0.0, 0.0),
                std::cmp::Ordering::Greater => (1.0, 0.0),
            },
            _ => (self.to_float(a, sa)?, self.to_float(b, sb)?),
        };
        Ok(compare_floats(p, x, y))
    }

    fn unary(&mut self) -> R<(Value, Span)> {
        let tok = self.peek()?;
        if let Some(p) = unary_operator(&tok) {
            self.next()?;
            self.enter(tok.span)?;
            let r = self.unary();
            self.leave();
            let (v, span) = r?;
            let span = tok.span.join(span);
            return Ok((self.apply_unary(p, v, span)?, span));
        }
        self.postfix()
    }

    /// `-v`, `+v` or `!v`.
    pub(super) fn apply_unary(&self, p: Punct, v: Value, span: Span) -> R<Value> {
        if let Value::Float(x) = v
            && p != Punct::Plus
        {
            return Ok(Value::Float(float_unary(p, x)));
        }
        match p {
            Punct::Minus => negate(&v).map_err(|m| self.err(span, m)),
            Punct::Bang => Ok(Value::Float(f64::from(u8::from(!self.truthy(&v, span)?)))),
            _ => Ok(v),
        }
    }

    pub(super) fn postfix(&mut self) -> R<(Value, Span)> {
        let (mut v, mut span) = self.primary()?;
        loop {
            let tok = self.peek_operator()?;
            if tok.is_punct(Punct::Dot) {
                self.next()?;
                let name = self.next()?;
                let Some(field) = name.ident() else {
                    return Err(self.expected("a component name like `x` after `.`", &name));
                };
                span = span.join(name.span);
                v = self.component(&v, field, span)?;
            } else if tok.is_punct(Punct::LBracket) && matches!(v, Value::Array(_)) {
                v = self.index_array(&v)?;
            } else {
                break;
            }
        }
        Ok((v, span))
    }

    pub(super) fn component(&self, v: &Value, field: &str, span: Span) -> R<Value> {
        let (c, colour) = match v {
            Value::Vector(v) => (v.c, false),
            Value::Colour(c) => (*c, true),
            Value::Float(f) => ([*f; 5], false),
            other => {
                return Err(self.err(
                    span,
                    format!(
                        "`.{field}` needs a vector or colour, found {}",
                        other.kind_name()
                    ),
                ));
            }
        };
        let i = match field {
            "x" | "u" | "red" => 0,
            "y" | "v" | "green" => 1,
            "z" | "blue" => 2,
            "t" if !colour => 3,
            "filter" | "f" => 3,
            "transmit" | "t" => 4,
            "gray" | "grey" => {
                return Ok(Value::Float(0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2]));
            }
            other => return Err(self.err(span, format!("unknown component `.{other}`"))),
        };
        Ok(Value::Float(c[i]))
    }

    fn primary(&mut self) -> R<(Value, Span)> {
        let tok = self.peek()?;
        match &tok.kind {
            TokenKind::Number(n) => {
                self.next()?;
                Ok((Value::Float(*n), tok.span))
            }
            TokenKind::Str(s) => {
                self.next()?;
                Ok((Value::Str(std::rc::Rc::from(*s)), tok.span))
            }
            TokenKind::Punct(Punct::LParen) => {
                self.next()?;
                let saved = std::mem::replace(&mut self.in_vector, false);
                self.grouping += 1;
                let r = self.expr();
                self.grouping -= 1;
                self.in_vector = saved;
                let (v, _) = r?;
                let close = self.expect(Punct::RParen, "to close the parenthesis")?;
                Ok((v, tok.span.join(close.span)))
            }
            TokenKind::Punct(Punct::Lt) => self.vector_literal(),
            TokenKind::Ident(name) => self.ident_value(&tok, name),
            _ => Err(self.expected("an expression", &tok)),
        }
    }

    fn vector_literal(&mut self) -> R<(Value, Span)> {
        let open = self.next()?;
        self.enter(open.span)?;
        let saved = std::mem::replace(&mut self.in_vector, true);
        let grouping = std::mem::take(&mut self.grouping);
        let r = self.vector_items();
        self.grouping = grouping;
        self.in_vector = saved;
        self.leave();
        let (c, len) = r?;
        let close = self.expect(Punct::Gt, "to close the vector")?;
        Ok((Value::Vector(Vector { c, len }), open.span.join(close.span)))
    }

    fn vector_items(&mut self) -> R<([f64; 5], u8)> {
        let mut c = [0.0; 5];
        let mut len = 0u8;
        loop {
            let (v, span) = match self.lone_operand() {
                Some(operand) => operand,
                None => self.ternary()?,
            };
            if len >= 5 {
                return Err(self.err(span, "a vector has at most 5 components"));
            }
            c[len as usize] = self.to_float(&v, span)?;
            len += 1;
            // A trailing comma is allowed: `<1, 2, 3,>`.
            if self.eat(Punct::Comma)? {
                if self.peek()?.is_punct(Punct::Gt) {
                    break;
                }
                continue;
            }
            if !starts_next_component(&self.peek()?) {
                break;
            }
        }
        if len < 2 {
            let tok = self.peek()?;
            return Err(self.expected("`,` (a vector has at least 2 components)", &tok));
        }
        Ok((c, len))
    }

    fn ident_value(&mut self, tok: &Token, name: &str) -> R<(Value, Span)> {
        let span = tok.span;
        let constant = |f: f64| Some(Value::Float(f));
        let value = fixed_constant(name).or_else(|| match name {
            "image_width" => constant(f64::from(self.image_width)),
            "image_height" => constant(f64::from(self.image_height)),
            "version" => constant(self.scene.version),
            _ => animation_value(&self.clock, name).and_then(|f| {
                // The scene depends on the frame: the render job must rebuild it.
                self.inputs.read_clock.set(true);
                constant(f)
            }),
        });
        if let Some(v) = value {
            self.next()?;
            return Ok((v, span));
        }
        if super::keywords::is_colour_keyword(name) {
            let (c, span) = self.colour()?;
            return Ok((Value::Colour(c), span));
        }
        if let Some(v) = self.lookup(name) {
            let v = v.clone();
            self.next()?;
            if let Value::Function(f) = &v {
                return self.call_declared_function(tok, f);
            }
            if let Value::Spline(s) = &v
                && self.peek()?.is_punct(Punct::LParen)
            {
                return self.call_spline(tok, s);
            }
            return Ok((v, span));
        }
        match functions::builtin(name) {
            Some(b) if b.is_supported() => {
                self.next()?;
                return self.call_function(tok, b);
            }
            Some(_) => return Err(self.unsupported(tok, name)),
            None => {}
        }
        if super::keywords::is_keyword(name) {
            return Err(self.expected("an expression", tok));
        }
        // Also a name called as a function that is neither built in nor a macro (macro
        // calls never get here): it gets the same hint as any unknown name.
        Err(self.unknown_identifier(tok, name))
    }

    /// `color ...`: an optional `color` keyword, then `rgb`-style keywords, component
    /// keywords (`red 1 green 0.5`) or an expression, in any combination.
    pub(super) fn colour(&mut self) -> R<([f64; 5], Span)> {
        let first = self.peek()?;
        let mut span = first.span;
        if first.is_ident("color") || first.is_ident("colour") {
            self.next()?;
        }
        let mut c: Option<[f64; 5]> = None;
        loop {
            let tok = if c.is_some() {
                self.peek_operator()?
            } else {
                self.peek()?
            };
            let Some(word) = tok.ident() else {
                if c.is_none() {
                    let (v, s) = self.expr()?;
                    c = Some(self.to_colour(&v, s)?);
                    span = span.join(s);
                    continue;
                }
                break;
            };
            match word {
                // A second `rgb...` starts the next colour (as in `checker rgb A rgb B`);
                // only component keywords may follow the first.
                "rgb" | "rgbf" | "rgbt" | "rgbft" | "srgb" | "srgbf" | "srgbt" | "srgbft"
                    if c.is_none() =>
                {
                    self.next()?;
                    self.enter(tok.span)?;
                    let r = self.additive();
                    self.leave();
                    let (v, s) = r?;
                    span = span.join(s);
                    c = Some(self.colour_from(word, &v, s)?);
                }
                "red" | "green" | "blue" | "filter" | "transmit" => {
                    self.next()?;
                    self.enter(tok.span)?;
                    let r = self.additive();
                    self.leave();
                    let (v, s) = r?;
                    span = span.join(s);
                    let f = self.to_float(&v, s)?;
                    let i = match word {
                        "red" => 0,
                        "green" => 1,
                        "blue" => 2,
                        "filter" => 3,
                        _ => 4,
                    };
                    c.get_or_insert([0.0; 5])[i] = f;
                }
                _ if c.is_none() => {
                    let (v, s) = self.expr()?;
                    c = Some(self.to_colour(&v, s)?);
                    span = span.join(s);
                }
                _ => break,
            }
        }
        Ok((c.unwrap_or([0.0; 5]), span))
    }

    fn colour_from(&self, word: &str, v: &Value, span: Span) -> R<[f64; 5]> {
        let srgb = word.starts_with('s');
        let kind = word.trim_start_matches('s');
        let (c, len) = match v {
            Value::Float(f) => ([*f; 5], 5),
            Value::Vector(v) => (v.c, v.len as usize),
            Value::Colour(c) => (*c, 5),
            other => {
                return Err(self.err(
                    span,
                    format!(
                        "`{word}` needs a float or a vector, found {}",
                        other.kind_name()
                    ),
                ));
            }
        };
        let need = match kind {
            "rgb" => 3,
            "rgbf" | "rgbt" => 4,
            _ => 5,
        };
        if len < need {
            return Err(self.err(
                span,
                format!("`{word}` needs a vector of {need} components, found {len}"),
            ));
        }
        let mut out = [c[0], c[1], c[2], 0.0, 0.0];
        match kind {
            "rgbf" => out[3] = c[3],
            "rgbt" => out[4] = c[3],
            "rgbft" => {
                out[3] = c[3];
                out[4] = c[4];
            }
            _ => {}
        }
        if srgb {
            for x in &mut out[..3] {
                *x = srgb_decode(*x);
            }
        }
        Ok(out)
    }

    fn call_function(&mut self, tok: &Token, b: &Builtin) -> R<(Value, Span)> {
        let open = self.expect(Punct::LParen, &format!("after `{}`", b.name))?;
        self.enter(open.span)?;
        let r = self.function_body(tok, b);
        self.leave();
        r
    }

    fn function_body(&mut self, tok: &Token, b: &Builtin) -> R<(Value, Span)> {
        let name = b.name;
        if matches!(b.eval, functions::Eval::Defined) {
            let id = self.raw_next();
            let close = self.expect(Punct::RParen, "to close `defined(`")?;
            let defined = id
                .ident()
                .is_some_and(|n| self.lookup(n).is_some() || self.is_open_data_file(n));
            return Ok((
                Value::Float(f64::from(u8::from(defined))),
                tok.span.join(close.span),
            ));
        }
        let saved = std::mem::replace(&mut self.in_vector, false);
        let mut args: Vec<(Value, Span)> = Vec::new();
        let r = (|| -> R<Token> {
            if !self.peek()?.is_punct(Punct::RParen) {
                loop {
                    // trace's fourth argument names the variable that gets the normal.
                    args.push(if name == "trace" && args.len() == 3 {
                        placement_normal_name(self)?
                    } else {
                        self.expr()?
                    });
                    if !self.eat(Punct::Comma)? {
                        break;
                    }
                }
            }
            self.expect(Punct::RParen, &format!("to close `{name}(`"))
        })();
        self.in_vector = saved;
        let close = r?;
        let span = tok.span.join(close.span);
        let call = functions::Call {
            name,
            args: &args,
            span,
        };
        let v = self.apply_builtin(b, &call)?;
        Ok((v, span))
    }

    fn index_array(&mut self, v: &Value) -> R<Value> {
        let (item, span) = self.array_element(v)?;
        item.ok_or_else(|| self.err(span, "this array element has not been set"))
    }

    /// The element the indices after an array name select: `None` where it is not set.
    pub(super) fn array_element(&mut self, v: &Value) -> R<(Option<Value>, Span)> {
        let Value::Array(a) = v else {
            let tok = self.peek()?;
            return Err(self.expected("an array", &tok));
        };
        let a = a.clone();
        let mut indices = Vec::new();
        let mut span = self.peek()?.span;
        while indices.len() < a.borrow().dims.len()
            && self.peek_operator()?.is_punct(Punct::LBracket)
        {
            self.next()?;
            let (i, s) = self.expr()?;
            let i = self.to_float(&i, s)?;
            let close = self.expect(Punct::RBracket, "to close the index")?;
            span = span.join(close.span);
            indices.push((i, s));
        }
        let flat = self.flat_index(&a.borrow().dims, &indices, span)?;
        let item = a.borrow().items.get(flat).cloned().flatten();
        Ok((item, span))
    }

    pub(super) fn flat_index(&self, dims: &[usize], idx: &[(f64, Span)], span: Span) -> R<usize> {
        if idx.len() != dims.len() {
            return Err(self.err(
                span,
                format!(
                    "this array has {} dimensions, found {} indices",
                    dims.len(),
                    idx.len()
                ),
            ));
        }
        let mut flat = 0usize;
        for (&d, &(i, s)) in dims.iter().zip(idx) {
            if i < 0.0 || i as usize >= d {
                return Err(self.err(s, format!("index {i} is outside the array (size {d})")));
            }
            flat = flat * d + i as usize;
        }
        Ok(flat)
    }
}

use super::placement::normal_name as placement_normal_name;

/// Whether a float counts as true: farther from zero than POV-Ray's tolerance.
pub(super) fn is_true(x: f64) -> bool {
    x.abs() > EPSILON
}

/// `x p y` for any binary operator between floats, the one table the interpreter and the
/// compiled expressions share; `None` for a division by zero.
pub(super) fn float_binary(p: Punct, x: f64, y: f64) -> Option<f64> {
    let truth = |t: bool| f64::from(u8::from(t));
    Some(match p {
        Punct::Plus => x + y,
        Punct::Minus => x - y,
        Punct::Star => x * y,
        Punct::Slash if y == 0.0 => return None,
        Punct::Slash => x / y,
        Punct::Pipe => truth(is_true(x) || is_true(y)),
        Punct::Amp => truth(is_true(x) && is_true(y)),
        _ => truth(compare_floats(p, x, y)),
    })
}

/// `-x` or `!x` of a float.
pub(super) fn float_unary(p: Punct, x: f64) -> f64 {
    if p == Punct::Minus {
        -x
    } else {
        f64::from(u8::from(!is_true(x)))
    }
}

/// `x p y` for a comparison operator `p`.
pub(super) fn compare_floats(p: Punct, x: f64, y: f64) -> bool {
    // Equality has POV-Ray's tolerance, and so do `<=` and `>=` (measured: 0.5 +
    // 1e-12 <= 0.5 holds, 0.5 + 2e-10 <= 0.5 does not; `<` and `>` are strict), so
    // `#while (X <= 0.5)` stepping X by 0.01 from -0.5 runs 101 times.
    let equal = (x - y).abs() <= EPSILON;
    match p {
        Punct::Lt => x < y,
        Punct::Le => x < y || equal,
        Punct::Eq => equal,
        Punct::Ne => !equal,
        Punct::Ge => x > y || equal,
        _ => x > y,
    }
}

/// How an expression is read where it starts: inside `<...>` (where `>` closes the vector)
/// and inside parentheses (where `<` after a float compares).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) struct Context {
    pub in_vector: bool,
    pub grouped: bool,
}

/// The level of the operator `p` after an operand (a float or not), or None where `p` ends
/// the expression.
pub(super) fn operator_level(p: Punct, after_float: bool, context: Context) -> Option<Level> {
    Some(match p {
        Punct::Pipe => Level::Or,
        Punct::Amp => Level::And,
        Punct::Plus | Punct::Minus => Level::Additive,
        Punct::Star | Punct::Slash => Level::Multiplicative,
        // `box { <a> <b> }`: a `<` after a vector starts the next vector, and so does
        // one outside parentheses (measured: POV-Ray reads `poly { 4 <1, ...> }` as
        // order 4, and refuses `str(A < 0.3, 0, 0)`); inside a vector `>` closes it.
        Punct::Gt if context.in_vector => return None,
        Punct::Lt if !after_float || !context.grouped => return None,
        Punct::Lt | Punct::Le | Punct::Eq | Punct::Ne | Punct::Ge | Punct::Gt => Level::Comparison,
        _ => return None,
    })
}

/// Whether `next`, after an operand, cannot continue the expression: `,`, `;`, `:`, a
/// closing bracket, `>` inside a vector, or a name.
pub(super) fn ends_operand(next: &Token, in_vector: bool) -> bool {
    match next.kind {
        TokenKind::Punct(
            Punct::Comma
            | Punct::Semi
            | Punct::Colon
            | Punct::RParen
            | Punct::RBrace
            | Punct::RBracket,
        )
        | TokenKind::Ident(_) => true,
        TokenKind::Punct(Punct::Gt) => in_vector,
        _ => false,
    }
}

/// Whether `next` makes an operand more than a plain number or name: `.x`, `[i]`, `(`.
pub(super) fn continues_operand(next: &Token) -> bool {
    [Punct::Dot, Punct::LBracket, Punct::LParen]
        .iter()
        .any(|&p| next.is_punct(p))
}

/// Whether a vector's next component starts at `next` without a comma: old scenes separate
/// components with spaces only (`<0 20 0>`).
pub(super) fn starts_next_component(next: &Token) -> bool {
    matches!(
        next.kind,
        TokenKind::Number(_) | TokenKind::Ident(_) | TokenKind::Punct(Punct::LParen)
    )
}

/// The prefix operator `tok` is, if any.
pub(super) fn unary_operator(tok: &Token) -> Option<Punct> {
    [Punct::Minus, Punct::Plus, Punct::Bang]
        .into_iter()
        .find(|&p| tok.is_punct(p))
}

/// The built-in identifiers whose values never change: `pi`, `true`, `x` and the like.
pub(super) fn fixed_constant(name: &str) -> Option<Value> {
    let axis = |c: [f64; 5], len: u8| Some(Value::Vector(Vector { c, len }));
    match name {
        "pi" => Some(Value::Float(std::f64::consts::PI)),
        "true" | "yes" | "on" => Some(Value::Float(1.0)),
        "false" | "no" | "off" => Some(Value::Float(0.0)),
        "x" => axis([1.0, 0.0, 0.0, 0.0, 0.0], 3),
        "y" => axis([0.0, 1.0, 0.0, 0.0, 0.0], 3),
        "z" => axis([0.0, 0.0, 1.0, 0.0, 0.0], 3),
        "t" => axis([0.0, 0.0, 0.0, 1.0, 0.0], 4),
        "u" => axis([1.0, 0.0, 0.0, 0.0, 0.0], 2),
        "v" => axis([0.0, 1.0, 0.0, 0.0, 0.0], 2),
        _ => None,
    }
}

fn srgb_decode(v: f64) -> f64 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// The identifiers whose values change from frame to frame of an animation.
fn animation_value(clock: &crate::lang::AnimationClock, name: &str) -> Option<f64> {
    Some(match name {
        "clock" => clock.clock,
        "clock_delta" => clock.clock_delta,
        "clock_on" => f64::from(u8::from(clock.clock_on)),
        "frame_number" => clock.frame_number as f64,
        "initial_frame" => clock.initial_frame as f64,
        "final_frame" => clock.final_frame as f64,
        "initial_clock" => clock.initial_clock,
        "final_clock" => clock.final_clock,
        _ => return None,
    })
}
