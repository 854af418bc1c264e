//! `function { ... }` declarations: the body is read from the token stream into an
//! expression tree (with POV-Ray's function grammar, which is narrower than the scene
//! language's: no `!`, no `? :`, floats only) and compiled once; calls in scene expressions
//! run the compiled program.

use std::rc::Rc;
use std::sync::Arc;

use super::super::diagnostics::Span;
use super::super::syntax::{Punct, Token, TokenKind};
use super::Evaluator;
use super::value::Value;
use crate::function::{Body, Channel, Expr, Function, Internal, MAX_PARAMS, Math1, Math2, compile};
use crate::lang::diagnostics::Diagnostic;

type R<T> = Result<T, Diagnostic>;

/// Names a function body can use for its parameters: the declared list, or x, y, z
/// (with u and v as the first two).
struct Params {
    names: Vec<Rc<str>>,
    /// Whether u and v stand for the first two (only without a declared list).
    implicit: bool,
}

impl Params {
    fn index(&self, name: &str) -> Option<u8> {
        if let Some(i) = self.names.iter().position(|n| &**n == name) {
            return Some(i as u8);
        }
        match name {
            "u" if self.implicit => Some(0),
            "v" if self.implicit => Some(1),
            _ => None,
        }
    }
}

impl Evaluator<'_> {
    /// `function [(a, b, ...)] { body }`, at the keyword.
    pub(super) fn function_value(&mut self) -> R<Function> {
        let kw = self.next()?;
        self.function_after_keyword(kw.span)
    }

    /// The parameter list and body, after `function`.
    pub(super) fn function_after_keyword(&mut self, span: Span) -> R<Function> {
        let params = self.function_params()?;
        let open = self.expect(Punct::LBrace, "after `function`")?;
        self.enter(open.span)?;
        let r = self.function_body_block(&params, span);
        self.leave();
        let body = r?;
        self.expect(Punct::RBrace, "to close the function")?;
        let mut names = params.names;
        if let Body::Spline(_) = &body {
            // A spline function takes the time alone.
            names.truncate(1);
        }
        // `internal(N)` takes more parameters than x, y, z; they have no names.
        if let Body::Float(p) = &body {
            for i in names.len()..usize::from(p.arity) {
                names.push(Rc::from(format!("P{}", i - 3)));
            }
        }
        Ok(Function {
            params: names,
            body,
        })
    }

    /// A `function { ... }` whose value is read at points (isosurfaces, patterns), after
    /// the keyword at `span`: it must be float-valued.
    pub(super) fn point_function(&mut self, span: Span) -> R<Arc<crate::function::Program>> {
        let tok = self.peek()?;
        match self.function_after_keyword(span)?.body {
            Body::Float(p) => Ok(p),
            Body::Pigment(_) => Err(self.err(
                tok.span,
                "a pigment function gives a colour; a float function is needed here",
            )),
            Body::Spline(_) => Err(self.err(
                tok.span,
                "a spline function gives a vector; a float function is needed here",
            )),
            Body::Transform(_) => Err(self.err(
                tok.span,
                "a transform function gives a vector; a float function is needed here",
            )),
        }
    }

    fn function_params(&mut self) -> R<Params> {
        if !self.eat(Punct::LParen)? {
            return Ok(Params {
                names: ["x", "y", "z"].map(Rc::from).to_vec(),
                implicit: true,
            });
        }
        let mut names: Vec<Rc<str>> = Vec::new();
        if !self.peek()?.is_punct(Punct::RParen) {
            loop {
                let tok = self.raw_next();
                let Some(name) = tok.ident() else {
                    return Err(self.expected("a parameter name", &tok));
                };
                if names.iter().any(|n| &**n == name) {
                    return Err(self.err(tok.span, format!("parameter `{name}` is named twice")));
                }
                if names.len() == MAX_PARAMS {
                    return Err(self.err(
                        tok.span,
                        format!("a function takes at most {MAX_PARAMS} parameters"),
                    ));
                }
                names.push(Rc::from(name));
                if !self.eat(Punct::Comma)? {
                    break;
                }
            }
        }
        self.expect(Punct::RParen, "to close the parameter list")?;
        Ok(Params {
            names,
            implicit: false,
        })
    }

    fn function_body_block(&mut self, params: &Params, span: Span) -> R<Body> {
        let tok = self.peek()?;
        let arity = params.names.len();
        let expr = match tok.ident() {
            Some("pigment") => {
                self.next()?;
                let p = self.pigment_body(crate::scene::Pigment::default())?;
                return Ok(Body::Pigment(Arc::new(p)));
            }
            Some("spline") => {
                let s = self.spline_value()?;
                return Ok(Body::Spline(Arc::new(s)));
            }
            Some("transform") => {
                self.next()?;
                let t = self.transform_block()?;
                return Ok(Body::Transform(Arc::new(t)));
            }
            Some("pattern") => {
                self.next()?;
                let pattern = self.pattern_block()?;
                Expr::Pattern(Box::new(pattern), (0..3).map(Expr::Arg).collect())
            }
            Some("internal") => {
                let kw = self.next()?;
                let f = self.internal_number(kw.span)?;
                let n = f.arity() as u8;
                return self.compiled(
                    &Expr::Internal(f, (0..n).map(Expr::Arg).collect()),
                    n.into(),
                    span,
                );
            }
            _ => self.f_or(params)?,
        };
        let arity = if matches!(expr, Expr::Pattern(..)) {
            3
        } else {
            arity
        };
        self.compiled(&expr, arity, span)
    }

    fn compiled(&self, e: &Expr, arity: usize, span: Span) -> R<Body> {
        let p = compile(e, arity).map_err(|m| self.err(span, m.to_string()))?;
        Ok(Body::Float(Arc::new(p)))
    }

    /// `(N)` after `internal`.
    fn internal_number(&mut self, start: Span) -> R<Internal> {
        self.expect(Punct::LParen, "after `internal`")?;
        let n = self.float()?;
        let close = self.expect(Punct::RParen, "to close `internal(`")?;
        Internal::numbered(n as u32).ok_or_else(|| {
            self.err(
                start.join(close.span),
                format!("unsupported: internal function {n} is not supported yet"),
            )
        })
    }

    /// `{ pattern-type modifiers }` after `pattern`: read as a pigment block, whose pattern
    /// and transforms are kept.
    fn pattern_block(&mut self) -> R<(crate::scene::Transform, crate::scene::Pattern)> {
        let open = self.peek()?;
        let pig = self.pigment_body(crate::scene::Pigment::default())?;
        use crate::scene::PigmentKind as K;
        match pig.kind {
            K::List { pattern, .. }
            | K::ColourMap { pattern, .. }
            | K::PigmentMap { pattern, .. } => Ok((pig.transform, pattern)),
            _ => Err(self.err(open.span, "expected a pattern in `pattern { }`")),
        }
    }

    fn f_binary(
        &mut self,
        params: &Params,
        ops: &[(Punct, Math2)],
        operand: fn(&mut Self, &Params) -> R<Expr>,
    ) -> R<Expr> {
        let mut a = operand(self, params)?;
        'outer: loop {
            let tok = self.peek_operator()?;
            for (p, op) in ops {
                if tok.is_punct(*p) {
                    self.next()?;
                    let b = operand(self, params)?;
                    a = Expr::Math2(*op, Box::new(a), Box::new(b));
                    continue 'outer;
                }
            }
            return Ok(a);
        }
    }

    fn f_or(&mut self, params: &Params) -> R<Expr> {
        self.f_binary(params, &[(Punct::Pipe, Math2::Or)], Self::f_and)
    }

    fn f_and(&mut self, params: &Params) -> R<Expr> {
        self.f_binary(params, &[(Punct::Amp, Math2::And)], Self::f_comparison)
    }

    fn f_comparison(&mut self, params: &Params) -> R<Expr> {
        const OPS: &[(Punct, Math2)] = &[
            (Punct::Lt, Math2::Lt),
            (Punct::Le, Math2::Le),
            (Punct::Eq, Math2::Eq),
            (Punct::Ne, Math2::Ne),
            (Punct::Ge, Math2::Ge),
            (Punct::Gt, Math2::Gt),
        ];
        self.f_binary(params, OPS, Self::f_additive)
    }

    fn f_additive(&mut self, params: &Params) -> R<Expr> {
        const OPS: &[(Punct, Math2)] = &[(Punct::Plus, Math2::Add), (Punct::Minus, Math2::Sub)];
        self.f_binary(params, OPS, Self::f_multiplicative)
    }

    fn f_multiplicative(&mut self, params: &Params) -> R<Expr> {
        const OPS: &[(Punct, Math2)] = &[(Punct::Star, Math2::Mul), (Punct::Slash, Math2::Div)];
        self.f_binary(params, OPS, Self::f_unary)
    }

    fn f_unary(&mut self, params: &Params) -> R<Expr> {
        let tok = self.peek()?;
        if tok.is_punct(Punct::Minus) || tok.is_punct(Punct::Plus) {
            self.next()?;
            self.enter(tok.span)?;
            let r = self.f_unary(params);
            self.leave();
            let e = r?;
            return Ok(if tok.is_punct(Punct::Minus) {
                Expr::Neg(Box::new(e))
            } else {
                e
            });
        }
        self.f_primary(params)
    }

    fn f_primary(&mut self, params: &Params) -> R<Expr> {
        let tok = self.peek()?;
        match &tok.kind {
            TokenKind::Number(n) => {
                self.next()?;
                Ok(Expr::Const(*n))
            }
            TokenKind::Punct(Punct::LParen) => {
                self.next()?;
                self.enter(tok.span)?;
                let r = self.f_or(params);
                self.leave();
                let e = r?;
                self.expect(Punct::RParen, "to close the parenthesis")?;
                Ok(e)
            }
            TokenKind::Ident(name) => {
                let name: Rc<str> = Rc::from(*name);
                self.f_name(params, &tok, &name)
            }
            _ => Err(self.expected("an operand of the function", &tok)),
        }
    }

    fn f_name(&mut self, params: &Params, tok: &Token, name: &str) -> R<Expr> {
        if let Some(i) = params.index(name) {
            self.next()?;
            return Ok(Expr::Arg(i));
        }
        if let Some(f) = Math1::named(name) {
            self.next()?;
            let mut args = self.f_args(params, tok, name, 1..=1)?;
            return Ok(Expr::Math1(f, Box::new(args.remove(0))));
        }
        if let Some(f) = Math2::named(name) {
            self.next()?;
            let many = matches!(f, Math2::Max | Math2::Min);
            let args = self.f_args(params, tok, name, 2..=if many { 64 } else { 2 })?;
            let mut it = args.into_iter();
            let first = it.next().expect("two arguments");
            return Ok(it.fold(first, |a, b| Expr::Math2(f, Box::new(a), Box::new(b))));
        }
        match name {
            "select" => {
                self.next()?;
                return Ok(Expr::Select(self.f_args(params, tok, name, 3..=4)?));
            }
            "sum" | "prod" => {
                self.next()?;
                return self.f_fold(params, name == "prod");
            }
            _ => {}
        }
        match self.lookup(name).cloned() {
            Some(Value::Function(f)) => {
                self.next()?;
                self.f_call(params, tok, name, &f)
            }
            _ => self.f_constant(tok),
        }
    }

    /// Any other name is evaluated now as a scene expression operand (`pi`, `clock`, a
    /// declared float, `V.x`): POV-Ray captures such values when the function is declared.
    fn f_constant(&mut self, tok: &Token) -> R<Expr> {
        let (v, span) = self.postfix()?;
        match v {
            Value::Float(f) => Ok(Expr::Const(f)),
            other => Err(self.err(
                tok.span.join(span),
                format!(
                    "a function can use only floats, found {} (use a component like `.x`)",
                    other.kind_name()
                ),
            )),
        }
    }

    fn f_call(&mut self, params: &Params, tok: &Token, name: &str, f: &Function) -> R<Expr> {
        let n = f.params.len();
        let args = self.f_args(params, tok, name, n..=n)?;
        match &f.body {
            Body::Float(p) => Ok(Expr::Call(p.clone(), args)),
            Body::Pigment(p) => {
                self.expect(Punct::Dot, &format!("after `{name}(...)`: a pigment function gives a colour; read a channel like `.red`"))?;
                let field = self.next()?;
                let ch = field.ident().and_then(Channel::named).ok_or_else(|| {
                    self.expected(
                        "a colour channel (`red`, `green`, `blue`, `filter`, `transmit`, `gray`)",
                        &field,
                    )
                })?;
                Ok(Expr::Pigment(Box::new((**p).clone()), ch, args))
            }
            Body::Spline(s) => {
                self.expect(Punct::Dot, &format!("after `{name}(...)`: a spline function gives a vector; read a component like `.y`"))?;
                let field = self.next()?;
                let c = field.ident().and_then(vector_component).ok_or_else(|| {
                    self.expected("a vector component (`x`, `y`, `z`, `t`)", &field)
                })?;
                let t = args.into_iter().next().expect("one argument");
                Ok(Expr::Spline(s.clone(), c, Box::new(t)))
            }
            Body::Transform(_) => Err(self.err(
                tok.span,
                format!("unsupported: the transform function `{name}` inside another function"),
            )),
        }
    }

    /// `(i, from, to, body)` after `sum` or `prod`.
    fn f_fold(&mut self, params: &Params, product: bool) -> R<Expr> {
        self.expect(Punct::LParen, "after `sum` or `prod`")?;
        let var = self.raw_next();
        let Some(name) = var.ident() else {
            return Err(self.expected("the name of the counter", &var));
        };
        if params.names.len() >= MAX_PARAMS {
            return Err(self.err(var.span, "too many parameters and counters in one function"));
        }
        let mut inner = Params {
            names: params.names.clone(),
            implicit: params.implicit,
        };
        inner.names.push(Rc::from(name));
        self.expect(Punct::Comma, "after the counter")?;
        let from = self.f_or(params)?;
        self.expect(Punct::Comma, "after the start")?;
        let to = self.f_or(params)?;
        self.expect(Punct::Comma, "after the end")?;
        let body = self.f_or(&inner)?;
        self.expect(Punct::RParen, "to close the sum")?;
        Ok(Expr::Fold {
            product,
            from: Box::new(from),
            to: Box::new(to),
            body: Box::new(body),
        })
    }

    /// `(a, b, ...)` with a count in `range`.
    fn f_args(
        &mut self,
        params: &Params,
        tok: &Token,
        name: &str,
        range: std::ops::RangeInclusive<usize>,
    ) -> R<Vec<Expr>> {
        let open = self.expect(Punct::LParen, &format!("after `{name}`"))?;
        self.enter(open.span)?;
        let r = self.f_arg_list(params);
        self.leave();
        let args = r?;
        let close = self.expect(Punct::RParen, &format!("to close `{name}(`"))?;
        if !range.contains(&args.len()) {
            let want = if range.start() == range.end() {
                range.start().to_string()
            } else {
                format!("{} to {}", range.start(), range.end())
            };
            return Err(self.err(
                tok.span.join(close.span),
                format!("`{name}` takes {want} arguments, found {}", args.len()),
            ));
        }
        Ok(args)
    }

    fn f_arg_list(&mut self, params: &Params) -> R<Vec<Expr>> {
        let mut args = Vec::new();
        if self.peek()?.is_punct(Punct::RParen) {
            return Ok(args);
        }
        loop {
            args.push(self.f_or(params)?);
            if !self.eat(Punct::Comma)? {
                return Ok(args);
            }
        }
    }

    /// `F(a, b, ...)` in a scene expression, at the name: the value now.
    pub(super) fn call_declared_function(&mut self, tok: &Token, f: &Function) -> R<(Value, Span)> {
        let name = tok.ident().unwrap_or("function");
        self.expect(Punct::LParen, &format!("after `{name}`"))?;
        let mut args = Vec::new();
        let saved = std::mem::replace(&mut self.in_vector, false);
        let r = self.call_arguments(&mut args);
        self.in_vector = saved;
        let close = r?;
        let span = tok.span.join(close.span);
        if args.len() != f.params.len() {
            return Err(self.err(
                span,
                format!(
                    "`{name}` takes {} arguments, found {}",
                    f.params.len(),
                    args.len()
                ),
            ));
        }
        let v = match &f.body {
            Body::Float(p) => Value::Float(p.eval(&args)),
            Body::Pigment(p) => {
                let at = glam::DVec3::new(args[0], args[1], args[2]);
                let c = crate::appearance::evaluate_pigment(p, at);
                Value::Colour([c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit])
            }
            Body::Spline(s) => super::path_splines::spline_vector(s, args[0], None),
            Body::Transform(t) => {
                let at = glam::DVec3::new(args[0], args[1], args[2]);
                Value::Vector(super::value::Vector::new3(t.point(at)))
            }
        };
        Ok((v, span))
    }

    fn call_arguments(&mut self, args: &mut Vec<f64>) -> R<Token> {
        if !self.peek()?.is_punct(Punct::RParen) {
            loop {
                args.push(self.float()?);
                if !self.eat(Punct::Comma)? {
                    break;
                }
            }
        }
        self.expect(Punct::RParen, "to close the call")
    }
}

/// A vector component by name, as `.x` reads it: x, y, z, t and the colour names.
fn vector_component(name: &str) -> Option<u8> {
    Some(match name {
        "x" | "u" | "red" => 0,
        "y" | "v" | "green" => 1,
        "z" | "blue" => 2,
        "t" | "filter" => 3,
        "transmit" => 4,
        _ => return None,
    })
}
