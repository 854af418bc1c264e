//! From an expression tree to a flat program: operands first, then the operation, with
//! constant subtrees folded and the stack depth counted so evaluation can use a fixed
//! array.

use std::sync::Arc;

use super::{Channel, Internal, MAX_PARAMS, MAX_SLOTS, Math1, Math2, Op, Program};
use crate::scene::path_spline::PathSpline;
use crate::scene::{Pattern, Pigment, Transform};

/// A function body as the parser reads it.
#[derive(Clone, Debug)]
pub enum Expr {
    Const(f64),
    Arg(u8),
    Neg(Box<Expr>),
    Math1(Math1, Box<Expr>),
    Math2(Math2, Box<Expr>, Box<Expr>),
    /// `select(a, b, c)` or `select(a, b, c, d)`.
    Select(Vec<Expr>),
    Call(Arc<Program>, Vec<Expr>),
    Internal(Internal, Vec<Expr>),
    /// A pattern read at the point the three expressions give.
    Pattern(Box<(Transform, Pattern)>, Vec<Expr>),
    Pigment(Box<Pigment>, Channel, Vec<Expr>),
    /// A spline's component (0 for x ... 4) at the argument.
    Spline(Arc<PathSpline>, u8, Box<Expr>),
    /// `sum(i, from, to, body)` or `prod`: `body` sees the caller's parameters and then i.
    Fold {
        product: bool,
        from: Box<Expr>,
        to: Box<Expr>,
        body: Box<Expr>,
    },
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CompileError {
    TooDeep,
    TooManyParameters,
}

impl std::fmt::Display for CompileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CompileError::TooDeep => write!(
                f,
                "this function is too large (it needs more than {MAX_SLOTS} values at once)"
            ),
            CompileError::TooManyParameters => {
                write!(f, "a function takes at most {MAX_PARAMS} parameters")
            }
        }
    }
}

type R<T> = Result<T, CompileError>;

/// Compiles a body for a function of `arity` parameters.
pub fn compile(expr: &Expr, arity: usize) -> R<Program> {
    if arity > MAX_PARAMS {
        return Err(CompileError::TooManyParameters);
    }
    let expr = fold(expr);
    let mut consts = Vec::new();
    collect_constants(&expr, &mut consts);
    let base = arity + consts.len();
    if base > MAX_SLOTS {
        return Err(CompileError::TooDeep);
    }
    let mut e = Emitter {
        arity,
        consts,
        base,
        depth: 0,
        most: 0,
        code: Vec::new(),
        calls: Vec::new(),
        patterns: Vec::new(),
        pigments: Vec::new(),
        splines: Vec::new(),
    };
    let result = e.operand(&expr)?;
    let slots = base + e.most;
    let mut preset = vec![0.0; super::run_size(slots)];
    preset[arity..base].copy_from_slice(&e.consts);
    Ok(Program {
        arity: arity as u8,
        slots: slots as u8,
        result,
        arithmetic: e.code.iter().all(Op::is_arithmetic),
        preset: preset.into(),
        code: e.code.into(),
        calls: e.calls.into(),
        patterns: e.patterns.into(),
        pigments: e.pigments.into(),
        splines: e.splines.into(),
    })
}

/// Every distinct constant, in the order met.
fn collect_constants(e: &Expr, out: &mut Vec<f64>) {
    let mut add = |c: f64| {
        if !out.iter().any(|o| o.to_bits() == c.to_bits()) {
            out.push(c);
        }
    };
    match e {
        Expr::Const(c) => add(*c),
        Expr::Arg(_) => {}
        Expr::Neg(a) | Expr::Math1(_, a) | Expr::Spline(_, _, a) => collect_constants(a, out),
        Expr::Math2(_, a, b) => {
            collect_constants(a, out);
            collect_constants(b, out);
        }
        Expr::Select(args)
        | Expr::Call(_, args)
        | Expr::Internal(_, args)
        | Expr::Pattern(_, args)
        | Expr::Pigment(_, _, args) => args.iter().for_each(|a| collect_constants(a, out)),
        Expr::Fold { from, to, .. } => {
            collect_constants(from, out);
            collect_constants(to, out);
        }
    }
}

struct Emitter {
    arity: usize,
    consts: Vec<f64>,
    /// The first temporary slot (after parameters and constants).
    base: usize,
    /// Temporaries in use, and the most ever in use.
    depth: usize,
    most: usize,
    code: Vec<Op>,
    calls: Vec<Arc<Program>>,
    patterns: Vec<(Transform, Pattern)>,
    pigments: Vec<Pigment>,
    splines: Vec<Arc<PathSpline>>,
}

impl Emitter {
    /// The next free temporary.
    fn temp(&mut self) -> R<u8> {
        let slot = self.base + self.depth;
        if slot >= MAX_SLOTS {
            return Err(CompileError::TooDeep);
        }
        self.depth += 1;
        self.most = self.most.max(self.depth);
        Ok(slot as u8)
    }

    /// The slot holding the expression's value, emitting what computes it.
    fn operand(&mut self, e: &Expr) -> R<u8> {
        match e {
            Expr::Arg(i) => Ok(*i),
            Expr::Const(c) => {
                let i = self.consts.iter().position(|o| o.to_bits() == c.to_bits());
                Ok((self.arity + i.expect("collected")) as u8)
            }
            _ => self.node(e),
        }
    }

    /// Operands in any slots; the result takes the first temporary they freed.
    fn operands<const N: usize>(&mut self, args: [&Expr; N]) -> R<([u8; N], u8)> {
        let start = self.depth;
        let mut slots = [0u8; N];
        for (slot, a) in slots.iter_mut().zip(args) {
            *slot = self.operand(a)?;
        }
        self.depth = start;
        Ok((slots, self.temp()?))
    }

    /// Arguments in consecutive slots (a call's, a pattern's point): the first slot, and
    /// the result's.
    fn consecutive(&mut self, args: &[Expr]) -> R<(u8, u8)> {
        let start = self.depth;
        let first = (self.base + start) as u8;
        for a in args {
            let want = (self.base + self.depth) as u8;
            match a {
                Expr::Arg(_) | Expr::Const(_) => {
                    let from = self.operand(a)?;
                    let to = self.temp()?;
                    self.code.push(Op::Copy(from, to));
                }
                _ => {
                    let got = self.node(a)?;
                    debug_assert_eq!(got, want);
                }
            }
        }
        self.depth = start;
        Ok((first, self.temp()?))
    }

    fn node(&mut self, e: &Expr) -> R<u8> {
        let (op, d) = match e {
            Expr::Neg(a) => {
                let ([a], d) = self.operands([&**a])?;
                (Op::Neg(a, d), d)
            }
            Expr::Math1(f, a) => {
                let ([a], d) = self.operands([&**a])?;
                (Op::Math1(*f, a, d), d)
            }
            Expr::Math2(f @ (Math2::Add | Math2::Sub), a, b)
                if product(a).or(product(b)).is_some() =>
            {
                return self.fused(*f, a, b);
            }
            Expr::Math2(f, a, b) => {
                let ([a, b], d) = self.operands([&**a, &**b])?;
                let op = match f {
                    Math2::Add => Op::Add(a, b, d),
                    Math2::Sub => Op::Sub(a, b, d),
                    Math2::Mul => Op::Mul(a, b, d),
                    Math2::Div => Op::Div(a, b, d),
                    _ => Op::Math2(*f, a, b, d),
                };
                (op, d)
            }
            Expr::Select(args) if args.len() == 3 => {
                let (s, d) = self.operands([&args[0], &args[1], &args[2]])?;
                (Op::Select3(s, d), d)
            }
            Expr::Select(args) => {
                let (s, d) = self.operands([&args[0], &args[1], &args[2], &args[3]])?;
                (Op::Select4(s, d), d)
            }
            Expr::Call(p, args) => {
                let (a, d) = self.consecutive(args)?;
                match p.wrapped_internal() {
                    // functions.inc's declarations: the internal function without the
                    // frame of a call (stackergold's rounded boxes: a quarter of its instructions).
                    Some(f) => (Op::Internal(f, a, f.arity() as u8, d), d),
                    None => {
                        self.calls.push(p.clone());
                        (Op::Call(self.calls.len() as u32 - 1, a, d), d)
                    }
                }
            }
            Expr::Internal(f, args) => {
                let (a, d) = self.consecutive(args)?;
                (Op::Internal(*f, a, f.arity() as u8, d), d)
            }
            Expr::Pattern(p, args) => {
                let (a, d) = self.consecutive(args)?;
                self.patterns.push((**p).clone());
                (Op::Pattern(self.patterns.len() as u32 - 1, a, d), d)
            }
            Expr::Pigment(p, ch, args) => {
                let (a, d) = self.consecutive(args)?;
                self.pigments.push((**p).clone());
                (Op::Pigment(self.pigments.len() as u32 - 1, *ch, a, d), d)
            }
            Expr::Spline(spline, c, t) => {
                let ([a], d) = self.operands([&**t])?;
                self.splines.push(spline.clone());
                (Op::Spline(self.splines.len() as u32 - 1, *c, a, d), d)
            }
            Expr::Fold {
                product,
                from,
                to,
                body,
            } => {
                let ([a, b], d) = self.operands([&**from, &**to])?;
                self.calls.push(Arc::new(compile(body, self.arity + 1)?));
                let i = self.calls.len() as u32 - 1;
                (
                    if *product {
                        Op::Prod(i, a, b, d)
                    } else {
                        Op::Sum(i, a, b, d)
                    },
                    d,
                )
            }
            Expr::Const(_) | Expr::Arg(_) => unreachable!("leaves have slots of their own"),
        };
        self.code.push(op);
        Ok(d)
    }
}

/// The two factors of a product.
type Factors<'a> = (&'a Expr, &'a Expr);

/// The factors of a product.
fn product(e: &Expr) -> Option<Factors<'_>> {
    match e {
        Expr::Math2(Math2::Mul, a, b) => Some((a, b)),
        _ => None,
    }
}

/// The two products of `a * b + c * d`.
fn sum_of_products(e: &Expr) -> Option<(Factors<'_>, Factors<'_>)> {
    match e {
        Expr::Math2(Math2::Add, a, b) => Some((product(a)?, product(b)?)),
        _ => None,
    }
}

impl Emitter {
    /// `a + b` or `a - b` where one side is a product, or both are, as one operation.
    fn fused(&mut self, f: Math2, a: &Expr, b: &Expr) -> R<u8> {
        if let (Math2::Add, Some((p, q)), Some((z, w))) = (f, sum_of_products(a), product(b)) {
            let ((x, y), (u, v)) = (p, q);
            let (slots, d) = self.operands([x, y, u, v, z, w])?;
            self.code.push(Op::MulMulMulAdd(slots, d));
            return Ok(d);
        }
        if let (Some((x, y)), Some((z, w))) = (product(a), product(b)) {
            let (slots, d) = self.operands([x, y, z, w])?;
            self.code.push(if f == Math2::Add {
                Op::MulMulAdd(slots, d)
            } else {
                Op::MulMulSub(slots, d)
            });
            return Ok(d);
        }
        let (x, y, c, op): (_, _, _, fn([u8; 3], u8) -> Op) = match (product(a), product(b)) {
            (Some((x, y)), _) if f == Math2::Add => (x, y, b, Op::MulAdd),
            (Some((x, y)), _) => (x, y, b, Op::MulSub),
            (None, Some((x, y))) if f == Math2::Add => (x, y, a, Op::MulAdd),
            (None, Some((x, y))) => (x, y, a, Op::SubMul),
            (None, None) => unreachable!("the caller saw a product"),
        };
        let (slots, d) = self.operands([x, y, c])?;
        self.code.push(op(slots, d));
        Ok(d)
    }
}

/// Folds operations whose operands are all constants.
fn fold(e: &Expr) -> Expr {
    let constant = |e: &Expr| match e {
        Expr::Const(c) => Some(*c),
        _ => None,
    };
    match e {
        Expr::Neg(a) => match fold(a) {
            Expr::Const(c) => Expr::Const(-c),
            a => Expr::Neg(Box::new(a)),
        },
        Expr::Math1(f, a) => match fold(a) {
            Expr::Const(c) => Expr::Const(super::math1(*f, c)),
            a => Expr::Math1(*f, Box::new(a)),
        },
        Expr::Math2(f, a, b) => match (fold(a), fold(b)) {
            (Expr::Const(x), Expr::Const(y)) => Expr::Const(super::math2(*f, x, y)),
            (a, b) => Expr::Math2(*f, Box::new(a), Box::new(b)),
        },
        Expr::Select(args) => {
            let args: Vec<Expr> = args.iter().map(fold).collect();
            match args.first().and_then(constant) {
                Some(s) if args.len() == 3 => args[if s < 0.0 { 1 } else { 2 }].clone(),
                Some(s) => args[if s < 0.0 {
                    1
                } else if s == 0.0 {
                    2
                } else {
                    3
                }]
                .clone(),
                None => Expr::Select(args),
            }
        }
        Expr::Call(p, args) => Expr::Call(p.clone(), args.iter().map(fold).collect()),
        Expr::Internal(f, args) => Expr::Internal(*f, args.iter().map(fold).collect()),
        Expr::Pattern(p, args) => Expr::Pattern(p.clone(), args.iter().map(fold).collect()),
        Expr::Pigment(p, ch, args) => {
            Expr::Pigment(p.clone(), *ch, args.iter().map(fold).collect())
        }
        Expr::Spline(s, c, t) => Expr::Spline(s.clone(), *c, Box::new(fold(t))),
        Expr::Fold {
            product,
            from,
            to,
            body,
        } => Expr::Fold {
            product: *product,
            from: Box::new(fold(from)),
            to: Box::new(fold(to)),
            body: body.clone(),
        },
        Expr::Const(_) | Expr::Arg(_) => e.clone(),
    }
}
