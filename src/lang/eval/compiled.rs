//! Expressions compiled once where the evaluator reads them again: in the bodies of
//! `#while` and `#for` loops, `#while` conditions and macros. The token-stream interpreter (expr.rs) read a
//! loop body's expressions token by token on every pass, and that descent was about half
//! of what a loop of a million objects cost (issue 16). The first time an expression is met
//! at a place (file, token, context) it is read here, without running anything, into a
//! small stack program; later passes run the program and jump to where it ends.
//!
//! Only a subset compiles: numbers, names holding floats or vectors, `pi` and the axis
//! constants, the binary and unary operators, parentheses, vector literals, `.x`-style
//! components, the built-in functions of one float (`sin`, `sqrt`, `int`, ...) and those
//! of [`CALLS`] (`mod`, `pow`, `vrotate`, `rand`, ...), and `? :` inside brackets (where
//! the span it gives does not depend on the branch taken). Anything else within reach
//! (another call, a string, a colour keyword, a directive, the frame's end) leaves the
//! expression to the interpreter. So does every run in which a name no longer holds the
//! kind it held when the expression was compiled (the kinds decide how the tokens parse:
//! `<` after a float compares, after a vector it starts the next one) and every run whose
//! arithmetic or call fails: the interpreter then reads the same tokens and gives the same
//! value or error. Nothing compiled has a side effect but `rand`'s, and a failed run puts
//! the random streams it advanced back first.

use std::collections::HashMap;
use std::hash::BuildHasherDefault;
use std::rc::Rc;

use super::super::diagnostics::Span;
use super::super::syntax::{Name, Punct, Token, TokenKind};
use super::expr::{
    Context, Level, continues_operand, ends_operand, fixed_constant, float_binary, float_unary,
    is_true, operator_level, starts_next_component, unary_operator,
};
use super::functions;
use super::stream::{Cond, FrameKind, NameHasher};
use super::value::{Value, Vector};
use super::{Evaluator, MAX_DEPTH};

/// Which reading an expression starts with: a full expression, or one of `+ -` and
/// tighter (a colour after `rgb`, a map entry's value).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum Entry {
    Expr,
    Additive,
}

/// Where an expression is read, and how: the same tokens read in another context are
/// another expression.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Site {
    file: u32,
    pos: u32,
    entry: Entry,
    context: Context,
}

/// The programs compiled so far, by site; `None` where the expression is not in the
/// subset (so it is not read twice to learn that).
#[derive(Default)]
pub(super) struct Programs {
    by_site: HashMap<Site, Option<Rc<Program>>, BuildHasherDefault<NameHasher>>,
    /// Off in the tests that compare the two ways of reading.
    pub disabled: bool,
    /// Reading a `#while` condition, which the loop's `#end` reads again.
    pub in_loop_condition: bool,
}

impl Programs {
    #[cfg(test)]
    fn compiled(&self) -> usize {
        self.by_site.values().flatten().count()
    }
}

/// One compiled expression.
struct Program {
    ops: Box<[Op]>,
    /// The value's kind.
    kind: Kind,
    /// The token index after the expression, where reading continues.
    end: usize,
    /// The span the interpreter gives the expression's value.
    span: Span,
    /// How deep the interpreter would nest reading it (against [`MAX_DEPTH`]).
    nesting: usize,
}

/// A name's kind when the expression was compiled; a run needs the same.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Float,
    Vector(u8),
}

impl Kind {
    fn of(v: &Value) -> Option<Kind> {
        match v {
            Value::Float(_) => Some(Kind::Float),
            Value::Vector(v) => Some(Kind::Vector(v.len)),
            _ => None,
        }
    }

    /// A value of this kind to type-check operations on: ones, so no division fails.
    fn sample(self) -> Value {
        match self {
            Kind::Float => Value::Float(1.0),
            Kind::Vector(len) => Value::Vector(Vector { c: [1.0; 5], len }),
        }
    }
}

/// The operations, typed when compiled: floats live on one stack, vectors on another, so
/// a loop's float arithmetic is a few instructions per operation.
#[derive(Clone, Copy, Debug)]
enum Op {
    Float(f64),
    LoadFloat(Name),
    /// An operator between two floats: arithmetic, comparison, `&`, `|`.
    FloatBinary(Punct),
    /// `-` or `!` before a float.
    FloatUnary(Punct),
    /// A built-in function of one float (`sin`, `sqrt`, `int`, ...).
    FloatCall(fn(f64) -> f64),
    /// Another built-in function of [`CALLS`].
    Call(NativeCall),
    Vector(Vector),
    LoadVector(Name, u8),
    /// Arithmetic with a vector on one side at least; whether each side is a float.
    VectorBinary(Punct, bool, bool),
    VectorNegate,
    /// `.x` and the like, of a vector.
    Component(Name),
    /// A vector literal from its components on the float stack.
    MakeVector(u8),
    /// `c ? a : b`, both branches evaluated (as the interpreter does).
    SelectFloat,
    SelectVector,
}

/// A call of a built-in function of [`CALLS`], with the kinds of its arguments.
#[derive(Clone, Copy, Debug)]
struct NativeCall {
    f: functions::Native,
    name: Name,
    argc: u8,
    /// Bit i set: argument i is a float (else a vector).
    floats: u8,
    result: Kind,
    /// `rand`: it advances a random stream, which a failed run restores.
    advances_stream: bool,
}

/// The built-in functions beyond those of one float that compile: the kind of their value,
/// and whether they take floats only (the others take vectors, or floats as vectors). All
/// are pure but `rand`, whose stream a failed run puts back before the interpreter reads
/// the expression again; `seed` (a new stream), `select` (a value of either kind) and the
/// rest stay with the interpreter.
const CALLS: &[(&str, Kind, bool)] = &[
    ("atan2", Kind::Float, true),
    ("bitwise_and", Kind::Float, true),
    ("bitwise_or", Kind::Float, true),
    ("bitwise_xor", Kind::Float, true),
    ("div", Kind::Float, true),
    ("max", Kind::Float, true),
    ("min", Kind::Float, true),
    ("mod", Kind::Float, true),
    ("pow", Kind::Float, true),
    ("rand", Kind::Float, true),
    ("vaxis_rotate", Kind::Vector(3), false),
    ("vcross", Kind::Vector(3), false),
    ("vdot", Kind::Float, false),
    ("vlength", Kind::Float, false),
    ("vnormalize", Kind::Vector(3), false),
    ("vrotate", Kind::Vector(3), false),
];

/// The most arguments of a compiled call, and the most `rand` calls in one expression.
const MAX_ARGS: usize = 4;
const MAX_RANDS: usize = 8;

/// The most floats a compiled expression holds at once.
const FLOATS: usize = 16;
/// The most vectors a compiled expression holds at once (few: the stacks are cleared per
/// run, and a vector is 48 bytes).
const VECTORS: usize = 4;

/// The two stacks a program runs on. The vectors' components and lengths are kept apart
/// so that clearing the stacks per run is a few aligned stores.
struct Stacks {
    floats: [f64; FLOATS],
    vectors: [[f64; 5]; VECTORS],
    lens: [u8; VECTORS],
    nf: usize,
    nv: usize,
    /// Random streams before the run's `rand` calls: (stream, state).
    undo: [(usize, u64); MAX_RANDS],
    nundo: usize,
}

impl Stacks {
    fn new() -> Stacks {
        Stacks {
            floats: [0.0; FLOATS],
            vectors: [[0.0; 5]; VECTORS],
            lens: [0; VECTORS],
            nf: 0,
            nv: 0,
            undo: [(0, 0); MAX_RANDS],
            nundo: 0,
        }
    }

    fn push_float(&mut self, x: f64) {
        self.floats[self.nf] = x;
        self.nf += 1;
    }

    fn pop_float(&mut self) -> f64 {
        self.nf -= 1;
        self.floats[self.nf]
    }

    fn push_vector(&mut self, v: Vector) {
        self.vectors[self.nv] = v.c;
        self.lens[self.nv] = v.len;
        self.nv += 1;
    }

    fn pop_vector(&mut self) -> Vector {
        self.nv -= 1;
        Vector {
            c: self.vectors[self.nv],
            len: self.lens[self.nv],
        }
    }

    /// An operand of a mixed operation, from the stack its kind lives on.
    fn pop_value(&mut self, float: bool) -> Value {
        if float {
            Value::Float(self.pop_float())
        } else {
            Value::Vector(self.pop_vector())
        }
    }
}

impl Evaluator<'_> {
    /// The value of the expression at the current token, from its compiled program, with
    /// the stream moved past it; `None` where the interpreter must read it.
    pub(super) fn run_compiled(&mut self, entry: Entry) -> Option<(Value, Span)> {
        if self.programs.disabled || !self.reads_again() {
            return None;
        }
        let frame = self.frames.last()?;
        let site = Site {
            file: frame.file.0,
            pos: u32::try_from(frame.pos).ok()?,
            entry,
            context: Context {
                in_vector: self.in_vector,
                grouped: self.grouping > 0,
            },
        };
        let program = match self.programs.by_site.get(&site) {
            Some(found) => found.clone()?,
            None => {
                let program = Compiler::new(self, entry)
                    .and_then(Compiler::finish)
                    .map(Rc::new);
                self.programs.by_site.insert(site, program.clone());
                program?
            }
        };
        let (value, end, span) = self.run_program(&program)?;
        self.set_frame_pos(end);
        Some((value, span))
    }

    /// Whether the current frame's tokens may be read again: a macro's body, a `#while`
    /// condition, or inside a loop opened in this frame. Elsewhere a program would be
    /// compiled to run once.
    fn reads_again(&self) -> bool {
        let Some(frame) = self.frames.last() else {
            return false;
        };
        self.programs.in_loop_condition
            || matches!(frame.kind, FrameKind::Macro { .. })
            || self.conds[frame.cond_base.min(self.conds.len())..]
                .iter()
                .any(|c| matches!(c, Cond::While { .. } | Cond::For { .. }))
    }

    /// The program's value, where it reads on and the span of what it read.
    fn run_program(&mut self, program: &Program) -> Option<(Value, usize, Span)> {
        if self.depth + program.nesting > MAX_DEPTH {
            return None;
        }
        let mut s = Stacks::new();
        for &op in &program.ops {
            if self.step(op, &mut s).is_none() {
                // The interpreter reads the expression again: as if this run never was.
                for &(stream, state) in s.undo[..s.nundo].iter().rev() {
                    self.rng_states[stream] = state;
                }
                return None;
            }
        }
        let value = if program.kind == Kind::Float {
            Value::Float(s.pop_float())
        } else {
            Value::Vector(s.pop_vector())
        };
        Some((value, program.end, program.span))
    }

    /// One operation on the stacks; `None` where the interpreter would report an error (or
    /// a name changed kind).
    fn step(&mut self, op: Op, s: &mut Stacks) -> Option<()> {
        let at = Span::DETACHED;
        match op {
            Op::Float(x) => s.push_float(x),
            Op::LoadFloat(name) => match self.lookup(name)? {
                Value::Float(x) => s.push_float(*x),
                _ => return None,
            },
            Op::FloatBinary(p) => {
                let y = s.pop_float();
                let x = s.pop_float();
                s.push_float(float_binary(p, x, y)?);
            }
            Op::FloatUnary(p) => {
                let x = s.pop_float();
                s.push_float(float_unary(p, x));
            }
            Op::FloatCall(f) => {
                let x = s.pop_float();
                s.push_float(f(x));
            }
            Op::Call(call) => self.native_call(call, s)?,
            Op::Vector(v) => s.push_vector(v),
            Op::LoadVector(name, len) => match self.lookup(name)? {
                Value::Vector(v) if v.len == len => s.push_vector(*v),
                _ => return None,
            },
            Op::VectorBinary(p, a_float, b_float) => {
                let b = s.pop_value(b_float);
                let a = s.pop_value(a_float);
                match self.apply(p, (&a, at), (&b, at), at).ok()? {
                    Value::Vector(v) => s.push_vector(v),
                    _ => return None,
                }
            }
            Op::VectorNegate => {
                let v = Value::Vector(s.pop_vector());
                match self.apply_unary(Punct::Minus, v, at).ok()? {
                    Value::Vector(v) => s.push_vector(v),
                    _ => return None,
                }
            }
            Op::Component(field) => {
                let v = Value::Vector(s.pop_vector());
                s.push_float(
                    self.to_float(&self.component(&v, field, at).ok()?, at)
                        .ok()?,
                );
            }
            Op::MakeVector(len) => {
                let mut c = [0.0; 5];
                for x in c[..usize::from(len)].iter_mut().rev() {
                    *x = s.pop_float();
                }
                s.push_vector(Vector { c, len });
            }
            Op::SelectFloat => {
                let b = s.pop_float();
                let a = s.pop_float();
                let c = s.pop_float();
                s.push_float(if is_true(c) { a } else { b });
            }
            Op::SelectVector => {
                let b = s.pop_vector();
                let a = s.pop_vector();
                let c = s.pop_float();
                s.push_vector(if is_true(c) { a } else { b });
            }
        }
        Some(())
    }
}

impl Evaluator<'_> {
    /// A call of [`CALLS`] on the stacks' top values, its random stream noted first.
    fn native_call(&mut self, call: NativeCall, s: &mut Stacks) -> Option<()> {
        let at = Span::DETACHED;
        let argc = usize::from(call.argc);
        let mut args: [(Value, Span); MAX_ARGS] = std::array::from_fn(|_| (Value::Float(0.0), at));
        for (i, arg) in args[..argc].iter_mut().enumerate().rev() {
            arg.0 = s.pop_value(call.floats & (1 << i) != 0);
        }
        if call.advances_stream
            && let Value::Float(i) = args[0].0
            && i >= 0.0
            && let Some(&state) = self.rng_states.get(i as usize)
        {
            s.undo[s.nundo] = (i as usize, state);
            s.nundo += 1;
        }
        let value = (call.f)(
            self,
            &functions::Call {
                name: call.name,
                args: &args[..argc],
                span: at,
            },
        )
        .ok()?;
        match (call.result, value) {
            (Kind::Float, Value::Float(x)) => s.push_float(x),
            (Kind::Vector(len), Value::Vector(v)) if v.len == len => s.push_vector(v),
            _ => return None,
        }
        Some(())
    }
}

/// Reads an expression's tokens as the interpreter would, without running anything, and
/// writes its program. Every reading mirrors the interpreter's function of the same name
/// (expr.rs); any token it cannot be sure of ends the attempt (`None`).
struct Compiler<'e, 'w> {
    ev: &'e Evaluator<'w>,
    tokens: &'e [Token],
    /// The frame's end: tokens at or past it belong to whoever reads after the frame.
    limit: usize,
    pos: usize,
    entry: Entry,
    in_vector: bool,
    grouping: u32,
    /// Brackets (parentheses, vectors) the reading is inside, counted from its start.
    enclosed: usize,
    nesting: usize,
    max_nesting: usize,
    ops: Vec<Op>,
    /// The stacks' depths after the operations so far.
    floats: usize,
    vectors: usize,
    /// `rand` calls so far (each notes its stream's state).
    rands: usize,
}

/// The most brackets and signs a compiled expression nests (deeper ones are read by the
/// interpreter, whose own limit then applies).
const MAX_COMPILED_NESTING: usize = 32;

impl<'e, 'w> Compiler<'e, 'w> {
    fn new(ev: &'e Evaluator<'w>, entry: Entry) -> Option<Compiler<'e, 'w>> {
        let frame = ev.frames.last()?;
        Some(Compiler {
            ev,
            tokens: &frame.tokens,
            limit: frame.end.min(frame.tokens.len()),
            pos: frame.pos,
            entry,
            in_vector: ev.in_vector,
            grouping: ev.grouping,
            enclosed: 0,
            nesting: 0,
            max_nesting: 0,
            ops: Vec::new(),
            floats: 0,
            vectors: 0,
            rands: 0,
        })
    }

    fn finish(mut self) -> Option<Program> {
        let (kind, span) = match self.entry {
            Entry::Expr => self.expr()?,
            Entry::Additive => self.binary(Level::Additive)?,
        };
        // The interpreter's caller reads on from here: the next token must be one the
        // stream hands over unchanged (not a directive, not past the frame).
        self.look(0)?;
        Some(Program {
            ops: self.ops.into_boxed_slice(),
            kind,
            end: self.pos,
            span,
            nesting: self.max_nesting,
        })
    }

    /// The token `ahead` of the current one, if it is one the stream would hand over as
    /// written: not a directive, not past the frame's end.
    fn look(&self, ahead: usize) -> Option<Token> {
        let i = self.pos + ahead;
        let tok = *self.tokens.get(i).filter(|_| i < self.limit)?;
        (!matches!(tok.kind, TokenKind::Directive(_))).then_some(tok)
    }

    fn context(&self) -> Context {
        Context {
            in_vector: self.in_vector,
            grouped: self.grouping > 0,
        }
    }

    fn enter(&mut self) -> Option<()> {
        self.nesting += 1;
        self.max_nesting = self.max_nesting.max(self.nesting);
        (self.nesting <= MAX_COMPILED_NESTING).then_some(())
    }

    fn leave(&mut self) {
        self.nesting -= 1;
    }

    fn expect(&mut self, p: Punct) -> Option<Token> {
        let tok = self.look(0).filter(|t| t.is_punct(p))?;
        self.pos += 1;
        Some(tok)
    }

    /// Appends an operation, keeping count of the stacks' depths.
    fn emit(&mut self, op: Op) -> Option<()> {
        let (pop_f, pop_v, push_f, push_v) = match op {
            Op::Float(_) | Op::LoadFloat(_) => (0, 0, 1, 0),
            Op::FloatBinary(_) => (2, 0, 1, 0),
            Op::FloatUnary(_) | Op::FloatCall(_) => (1, 0, 1, 0),
            Op::Call(c) => {
                let f = c.floats.count_ones() as usize;
                let v = usize::from(c.argc) - f;
                match c.result {
                    Kind::Float => (f, v, 1, 0),
                    Kind::Vector(_) => (f, v, 0, 1),
                }
            }
            Op::Vector(_) | Op::LoadVector(..) => (0, 0, 0, 1),
            Op::VectorBinary(_, a, b) => (
                usize::from(a) + usize::from(b),
                2 - usize::from(a) - usize::from(b),
                0,
                1,
            ),
            Op::VectorNegate => (0, 1, 0, 1),
            Op::Component(_) => (0, 1, 1, 0),
            Op::MakeVector(len) => (usize::from(len), 0, 0, 1),
            Op::SelectFloat => (3, 0, 1, 0),
            Op::SelectVector => (1, 2, 0, 1),
        };
        self.floats = self.floats.checked_sub(pop_f)? + push_f;
        self.vectors = self.vectors.checked_sub(pop_v)? + push_v;
        self.ops.push(op);
        (self.floats <= FLOATS && self.vectors <= VECTORS).then_some(())
    }

    /// The operation `a p b`, typed: between floats, or arithmetic with a vector (whose
    /// result's length the interpreter's own arithmetic gives, on sample values).
    fn binary_op(&mut self, p: Punct, a: Kind, b: Kind) -> Option<Kind> {
        if a == Kind::Float && b == Kind::Float {
            self.emit(Op::FloatBinary(p))?;
            return Some(Kind::Float);
        }
        if !matches!(p, Punct::Plus | Punct::Minus | Punct::Star | Punct::Slash) {
            return None;
        }
        let at = Span::DETACHED;
        let v = self
            .ev
            .apply(p, (&a.sample(), at), (&b.sample(), at), at)
            .ok()?;
        let kind = Kind::of(&v).filter(|k| *k != Kind::Float)?;
        self.emit(Op::VectorBinary(p, a == Kind::Float, b == Kind::Float))?;
        Some(kind)
    }

    fn expr(&mut self) -> Option<(Kind, Span)> {
        if let Some(operand) = self.lone_operand() {
            return Some(operand);
        }
        self.enter()?;
        let r = self.ternary()?;
        self.leave();
        Some(r)
    }

    fn lone_operand(&mut self) -> Option<(Kind, Span)> {
        if ends_operand(&self.look(1)?, self.in_vector) {
            self.plain_operand()
        } else {
            None
        }
    }

    fn plain_operand(&mut self) -> Option<(Kind, Span)> {
        let tok = self.look(0)?;
        if continues_operand(&self.look(1)?) {
            return None;
        }
        let op = match tok.kind {
            TokenKind::Number(n) => Op::Float(n),
            TokenKind::Ident(name) if !crate::lang::parse::is_interned_keyword(name) => {
                match self.ev.lookup(name)? {
                    Value::Float(_) => Op::LoadFloat(name),
                    _ => return None,
                }
            }
            _ => return None,
        };
        self.pos += 1;
        self.emit(op)?;
        Some((Kind::Float, tok.span))
    }

    fn ternary(&mut self) -> Option<(Kind, Span)> {
        let (c, span) = self.binary(Level::Or)?;
        if !self.look(0)?.is_punct(Punct::Question) {
            return Some((c, span));
        }
        // Outside brackets the expression's span ends at the branch taken.
        if self.enclosed == 0 || c != Kind::Float {
            return None;
        }
        self.pos += 1;
        let (a, _) = self.expr()?;
        self.expect(Punct::Colon)?;
        let (b, sb) = self.expr()?;
        let select = match (a, b) {
            (Kind::Float, Kind::Float) => Op::SelectFloat,
            _ if a == b => Op::SelectVector,
            _ => return None,
        };
        self.emit(select)?;
        Some((a, span.join(sb)))
    }

    fn binary(&mut self, level: Level) -> Option<(Kind, Span)> {
        let (mut a, mut span) = match self.plain_operand() {
            Some(operand) => operand,
            None => self.unary()?,
        };
        loop {
            let tok = self.look(0)?;
            let TokenKind::Punct(p) = tok.kind else {
                break;
            };
            let Some(op_level) = operator_level(p, a == Kind::Float, self.context()) else {
                break;
            };
            if op_level < level {
                break;
            }
            self.pos += 1;
            let (b, sb) = self.binary(op_level.tighter())?;
            a = self.binary_op(p, a, b)?;
            span = span.join(sb);
        }
        Some((a, span))
    }

    fn unary(&mut self) -> Option<(Kind, Span)> {
        let tok = self.look(0)?;
        let Some(p) = unary_operator(&tok) else {
            return self.postfix();
        };
        self.pos += 1;
        self.enter()?;
        let (v, span) = self.unary()?;
        self.leave();
        match (p, v) {
            (Punct::Plus, _) => {}
            (_, Kind::Float) => self.emit(Op::FloatUnary(p))?,
            (Punct::Minus, _) => self.emit(Op::VectorNegate)?,
            _ => return None,
        }
        Some((v, tok.span.join(span)))
    }

    fn postfix(&mut self) -> Option<(Kind, Span)> {
        let (mut v, mut span) = self.primary()?;
        while self.look(0)?.is_punct(Punct::Dot) {
            self.pos += 1;
            let name = self.look(0)?;
            let field = name.ident()?;
            self.pos += 1;
            span = span.join(name.span);
            // Of a vector only, and a field it has (`.x`, `.t`, ...).
            let at = Span::DETACHED;
            if v == Kind::Float || self.ev.component(&v.sample(), field, at).is_err() {
                return None;
            }
            self.emit(Op::Component(field))?;
            v = Kind::Float;
        }
        Some((v, span))
    }

    fn primary(&mut self) -> Option<(Kind, Span)> {
        let tok = self.look(0)?;
        match tok.kind {
            TokenKind::Number(n) => {
                self.pos += 1;
                self.emit(Op::Float(n))?;
                Some((Kind::Float, tok.span))
            }
            TokenKind::Punct(Punct::LParen) => {
                self.pos += 1;
                let saved = std::mem::replace(&mut self.in_vector, false);
                self.grouping += 1;
                self.enclosed += 1;
                let r = self.expr();
                self.enclosed -= 1;
                self.grouping -= 1;
                self.in_vector = saved;
                let (v, _) = r?;
                let close = self.expect(Punct::RParen)?;
                Some((v, tok.span.join(close.span)))
            }
            TokenKind::Punct(Punct::Lt) => self.vector_literal(),
            TokenKind::Ident(name) => self.ident_value(&tok, name),
            _ => None,
        }
    }

    fn vector_literal(&mut self) -> Option<(Kind, Span)> {
        let open = self.look(0)?;
        self.pos += 1;
        self.enter()?;
        let saved = std::mem::replace(&mut self.in_vector, true);
        let grouping = std::mem::take(&mut self.grouping);
        self.enclosed += 1;
        let r = self.vector_items();
        self.enclosed -= 1;
        self.grouping = grouping;
        self.in_vector = saved;
        self.leave();
        let len = r?;
        let close = self.expect(Punct::Gt)?;
        self.emit(Op::MakeVector(len))?;
        Some((Kind::Vector(len), open.span.join(close.span)))
    }

    fn vector_items(&mut self) -> Option<u8> {
        let mut len = 0u8;
        loop {
            let (v, _) = match self.lone_operand() {
                Some(operand) => operand,
                None => self.ternary()?,
            };
            if len >= 5 || v != Kind::Float {
                return None;
            }
            len += 1;
            if self.look(0)?.is_punct(Punct::Comma) {
                self.pos += 1;
                if self.look(0)?.is_punct(Punct::Gt) {
                    break;
                }
                continue;
            }
            if !starts_next_component(&self.look(0)?) {
                break;
            }
        }
        (len >= 2).then_some(len)
    }

    /// Constants, names holding a float or a vector, and calls of the built-in functions
    /// of one float; any other name (a colour keyword, another call, the clock) is the
    /// interpreter's.
    fn ident_value(&mut self, tok: &Token, name: Name) -> Option<(Kind, Span)> {
        let (op, kind) = match fixed_constant(name) {
            Some(Value::Float(f)) => (Op::Float(f), Kind::Float),
            Some(Value::Vector(v)) => (Op::Vector(v), Kind::Vector(v.len)),
            Some(_) => return None,
            None if crate::lang::parse::is_interned_keyword(name) => {
                let builtin = functions::builtin(name)?;
                return match builtin.eval {
                    functions::Eval::Float(f) => self.float_call(tok, f),
                    functions::Eval::Native(f) => self.native_call(tok, builtin, f),
                    _ => None,
                };
            }
            None => match Kind::of(self.ev.lookup(name)?)? {
                Kind::Float => (Op::LoadFloat(name), Kind::Float),
                Kind::Vector(len) => (Op::LoadVector(name, len), Kind::Vector(len)),
            },
        };
        // A name followed by `(` is a call, by `[` an index: neither compiles.
        if self.look(1)?.is_punct(Punct::LParen) {
            return None;
        }
        self.pos += 1;
        self.emit(op)?;
        Some((kind, tok.span))
    }
}

impl Compiler<'_, '_> {
    /// The arguments of a call, read as `function_body` reads them: outside any vector,
    /// the call one level deeper. Their kinds and the closing parenthesis's span.
    fn arguments(&mut self) -> Option<(Vec<Kind>, Span)> {
        self.expect(Punct::LParen)?;
        self.enter()?;
        let saved = std::mem::replace(&mut self.in_vector, false);
        self.enclosed += 1;
        let mut kinds = Vec::new();
        let mut read = || -> Option<()> {
            if self.look(0)?.is_punct(Punct::RParen) {
                return Some(());
            }
            loop {
                kinds.push(self.expr()?.0);
                if !self.look(0)?.is_punct(Punct::Comma) {
                    return Some(());
                }
                self.pos += 1;
            }
        };
        let r = read();
        self.enclosed -= 1;
        self.in_vector = saved;
        self.leave();
        r?;
        let close = self.expect(Punct::RParen)?;
        Some((kinds, close.span))
    }

    /// A call of a function of [`CALLS`] whose arguments have the kinds it takes, in a
    /// number it accepts.
    fn native_call(
        &mut self,
        name: &Token,
        builtin: &'static functions::Builtin,
        f: functions::Native,
    ) -> Option<(Kind, Span)> {
        let &(_, result, floats_only) = CALLS.iter().find(|c| c.0 == builtin.name)?;
        self.pos += 1;
        let (kinds, close) = self.arguments()?;
        if kinds.len() > MAX_ARGS || floats_only && kinds.iter().any(|&k| k != Kind::Float) {
            return None;
        }
        let at = Span::DETACHED;
        let samples: Vec<(Value, Span)> = kinds.iter().map(|k| (k.sample(), at)).collect();
        let call = functions::Call {
            name: builtin.name,
            args: &samples,
            span: at,
        };
        self.ev.check_arity(builtin.arity, &call).ok()?;
        let advances_stream = builtin.name == "rand";
        self.rands += usize::from(advances_stream);
        if self.rands > MAX_RANDS {
            return None;
        }
        let floats = kinds
            .iter()
            .enumerate()
            .filter(|&(_, &k)| k == Kind::Float)
            .fold(0u8, |m, (i, _)| m | 1 << i);
        self.emit(Op::Call(NativeCall {
            f,
            name: builtin.name,
            argc: kinds.len() as u8,
            floats,
            result,
            advances_stream,
        }))?;
        Some((result, name.span.join(close)))
    }

    /// `name(x)` for a built-in function of one float, read as `call_function` reads it:
    /// its argument outside any vector, the call one level deeper.
    fn float_call(&mut self, name: &Token, f: fn(f64) -> f64) -> Option<(Kind, Span)> {
        self.pos += 1;
        let (kinds, close) = self.arguments()?;
        // Another count (an arity error) or a vector (a type error) is the interpreter's
        // to report.
        if kinds != [Kind::Float] {
            return None;
        }
        self.emit(Op::FloatCall(f))?;
        Some((Kind::Float, name.span.join(close)))
    }
}

#[cfg(test)]
#[path = "compiled_tests.rs"]
mod tests;
