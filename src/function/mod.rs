//! User-defined functions (`function { ... }`), compiled once into a flat program for a
//! small register machine. Isosurfaces call them millions of times per image, so evaluation
//! allocates nothing: the registers are a fixed array whose size the compiler proves, and
//! calls to other functions run the callee's program on a fresh fixed array.
//!
//! Semantics measured with POV-Ray 3.7's `#debug` on declared functions: `select` with
//! three arguments takes the second for a negative first and the third otherwise, with four
//! the second, third or fourth for a negative, zero or positive first; comparisons and
//! `&`, `|` give 0 or 1 (`=` is exact); `mod` and `int` truncate as C does; float
//! identifiers are captured when the function is declared (a later `#declare` does not
//! change it); `u` and `v` are the first two parameters.

mod compile;
mod internal;

use glam::DVec3;

pub use compile::{CompileError, Expr, compile};
pub use internal::Internal;

use crate::scene::path_spline::PathSpline;
use crate::scene::{Pattern, Pigment, Transform};

/// Slots (parameters, constants, temporaries) a program may use; the compiler refuses
/// larger expressions.
pub const MAX_SLOTS: usize = 64;

/// The slot array `Program::run` uses for a program of `slots` slots.
fn run_size(slots: usize) -> usize {
    match slots {
        0..=8 => 8,
        9..=16 => 16,
        17..=32 => 32,
        _ => MAX_SLOTS,
    }
}

/// Most parameters a function may take (POV-Ray's own limit is lower in practice).
pub const MAX_PARAMS: usize = 16;

/// A compiled function: a float-valued program, or a pigment (whose calls give a colour).
#[derive(Clone, Debug, PartialEq)]
pub struct Function {
    pub params: Vec<std::rc::Rc<str>>,
    pub body: Body,
}

// The parameter names are only needed while compiling callers; the render shares the
// body across threads.
#[derive(Clone, Debug, PartialEq)]
pub enum Body {
    Float(std::sync::Arc<Program>),
    /// `function { pigment { ... } }`: called with x, y, z, it gives the pigment's colour.
    Pigment(std::sync::Arc<Pigment>),
    /// `function { spline { ... } }`: called with t, it gives the spline's vector.
    Spline(std::sync::Arc<PathSpline>),
    /// `function { transform { ... } }`: called with x, y, z, it gives the transformed point
    /// (transforms.inc's `vtransform` macro).
    Transform(std::sync::Arc<Transform>),
}

/// One function's code, with the side tables its operations index.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    pub arity: u8,
    /// Slots the code uses, and the one holding the value at the end.
    slots: u8,
    result: u8,
    /// Whether every operation is arithmetic (`Op::is_arithmetic`).
    arithmetic: bool,
    /// The slots as evaluation starts, before the arguments: the constants in place, the
    /// rest 0, as long as the array `run` uses (one fixed-size copy instead of zeroing and
    /// a loop over the constants).
    preset: Box<[f64]>,
    code: Box<[Op]>,
    calls: Box<[std::sync::Arc<Program>]>,
    /// `pattern { ... }` blocks: the pattern and the transforms written in the block.
    patterns: Box<[(Transform, Pattern)]>,
    pigments: Box<[Pigment]>,
    splines: Box<[std::sync::Arc<PathSpline>]>,
}

/// Float functions of one argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Math1 {
    Abs,
    Acos,
    Acosh,
    Asin,
    Asinh,
    Atan,
    Atanh,
    Ceil,
    Cos,
    Cosh,
    Degrees,
    Exp,
    Floor,
    Int,
    Ln,
    Log,
    Radians,
    Sin,
    Sinh,
    Sqrt,
    Tan,
    Tanh,
}

/// Float functions of two arguments, and the binary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Math2 {
    Add,
    Sub,
    Mul,
    Div,
    Lt,
    Le,
    Eq,
    Ne,
    Ge,
    Gt,
    And,
    Or,
    Atan2,
    Max,
    Min,
    Mod,
    Pow,
}

/// Colour channels a pigment function's call can be read through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channel {
    Red,
    Green,
    Blue,
    Filter,
    Transmit,
    Gray,
}

/// One operation: operands and result are slot numbers (parameters first, then the
/// constants, then temporaries), so parameters and constants cost no operation at all.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Op {
    Add(u8, u8, u8),
    Sub(u8, u8, u8),
    Mul(u8, u8, u8),
    Div(u8, u8, u8),
    Neg(u8, u8),
    Copy(u8, u8),
    /// a * b + c, a * b - c, c - a * b: two roundings, as the separate operations give,
    /// in one step (sums of products are most of what isosurface functions compute).
    MulAdd([u8; 3], u8),
    MulSub([u8; 3], u8),
    SubMul([u8; 3], u8),
    /// a * b + c * d and a * b - c * d (polynomials are sums of such pairs).
    MulMulAdd([u8; 4], u8),
    MulMulSub([u8; 4], u8),
    /// a * b + c * d + e * f, added left to right (the squared length of a vector).
    MulMulMulAdd([u8; 6], u8),
    Math1(Math1, u8, u8),
    Math2(Math2, u8, u8, u8),
    /// Selector, the alternatives, result.
    Select3([u8; 3], u8),
    Select4([u8; 4], u8),
    /// Callee, first of its consecutive argument slots, result.
    Call(u32, u8, u8),
    /// The function, its first argument's slot, its arity (found once: its table is
    /// searched for it), result.
    Internal(Internal, u8, u8, u8),
    /// Pattern, first of the x, y, z slots, result.
    Pattern(u32, u8, u8),
    Pigment(u32, Channel, u8, u8),
    /// Spline, component, the slot of t, result.
    Spline(u32, u8, u8, u8),
    /// `sum(i, a, b, expr)` and `prod`: the callee (whose last parameter is i) runs for
    /// i = a, a + 1, ... <= b, with the caller's parameters before i.
    Sum(u32, u8, u8, u8),
    Prod(u32, u8, u8, u8),
}

impl Op {
    /// The operations `run` computes inline.
    fn is_arithmetic(&self) -> bool {
        matches!(
            self,
            Op::Add(..)
                | Op::Sub(..)
                | Op::Mul(..)
                | Op::Div(..)
                | Op::Neg(..)
                | Op::Copy(..)
                | Op::MulAdd(..)
                | Op::MulSub(..)
                | Op::SubMul(..)
                | Op::MulMulAdd(..)
                | Op::MulMulSub(..)
                | Op::MulMulMulAdd(..)
        )
    }
}

impl Program {
    /// The function's value; `args` has exactly `arity` values.
    #[inline]
    pub fn eval(&self, args: &[f64]) -> f64 {
        // A small array for small functions: copying the largest on every call would cost
        // more than a short function's arithmetic.
        // Pure arithmetic runs in a loop that calls nothing, so it keeps its state in
        // registers the callee would otherwise make it save (a tenth of the instructions).
        match (self.preset.len(), self.arithmetic) {
            (8, true) => self.run_inline::<8, false>(args),
            (8, false) => self.run::<8, true>(args),
            (16, true) => self.run::<16, false>(args),
            (16, false) => self.run::<16, true>(args),
            (32, _) => self.run::<32, true>(args),
            _ => self.run::<MAX_SLOTS, true>(args),
        }
    }

    /// The internal function this one is, where it only passes its arguments on in order
    /// (`function { internal(n) }`: each argument copied to the call's slots, then the
    /// call), so that a caller can call it directly with the same values.
    pub(crate) fn wrapped_internal(&self) -> Option<Internal> {
        let (Op::Internal(f, first, _, d), copies) = self.code.split_last()? else {
            return None;
        };
        let n = usize::from(self.arity);
        let passed = copies.len() == n
            && f.arity() == n
            && *d == self.result
            && copies.iter().enumerate().all(|(k, op)| {
                matches!(*op, Op::Copy(a, b)
                    if usize::from(a) == k && usize::from(b) == usize::from(*first) + k)
            });
        passed.then_some(*f)
    }

    /// The value at a point, for isosurfaces and function patterns (x, y, z first).
    pub fn at(&self, p: DVec3) -> f64 {
        let mut args = [0.0; MAX_PARAMS];
        args[0] = p.x;
        args[1] = p.y;
        args[2] = p.z;
        self.eval(&args[..usize::from(self.arity).clamp(3, MAX_PARAMS)])
    }

    /// `OTHERS`: whether the code may hold operations other than arithmetic.
    #[inline(never)]
    fn run<const N: usize, const OTHERS: bool>(&self, args: &[f64]) -> f64 {
        self.run_inline::<N, OTHERS>(args)
    }

    /// [`Program::run`] where the caller wants it inline: the small arithmetic programs
    /// isosurfaces are made of, whose call would cost as much as their arithmetic.
    #[inline(always)]
    fn run_inline<const N: usize, const OTHERS: bool>(&self, args: &[f64]) -> f64 {
        // Slot numbers are below N (the compiler's bound, N a power of two), so masking
        // them changes nothing and lets the compiler drop the bounds checks.
        let at = |i: usize| i & (N - 1);
        // The compiler sized the preset for N: the fallback is never taken.
        let Some(Ok(preset)) = self.preset.get(..N).map(<&[f64; N]>::try_from) else {
            return f64::NAN;
        };
        let mut s = *preset;
        // Indexed copies: for a handful of values they beat both memcpy and iterator
        // adapters.
        if let ([x, y, z], 3) = (args, self.arity) {
            // Isosurfaces and function patterns: x, y, z, without a loop.
            (s[0], s[1], s[2]) = (*x, *y, *z);
        } else {
            let arity = usize::from(self.arity).min(args.len());
            for i in 0..arity {
                s[at(i)] = args[i];
            }
        }
        let at = |i: u8| at(usize::from(i));
        for op in self.code.iter() {
            // Arithmetic inline, the rest out of line, so the loop stays small and keeps
            // its registers (a third fewer instructions per operation, measured).
            match *op {
                Op::Add(a, b, d) => s[at(d)] = s[at(a)] + s[at(b)],
                Op::Sub(a, b, d) => s[at(d)] = s[at(a)] - s[at(b)],
                Op::Mul(a, b, d) => s[at(d)] = s[at(a)] * s[at(b)],
                Op::Div(a, b, d) => s[at(d)] = s[at(a)] / s[at(b)],
                Op::Neg(a, d) => s[at(d)] = -s[at(a)],
                Op::Copy(a, d) => s[at(d)] = s[at(a)],
                Op::MulAdd([a, b, c], d) => s[at(d)] = s[at(a)] * s[at(b)] + s[at(c)],
                Op::MulSub([a, b, c], d) => s[at(d)] = s[at(a)] * s[at(b)] - s[at(c)],
                Op::SubMul([a, b, c], d) => s[at(d)] = s[at(c)] - s[at(a)] * s[at(b)],
                Op::MulMulAdd([a, b, c, e], d) => {
                    s[at(d)] = s[at(a)] * s[at(b)] + s[at(c)] * s[at(e)];
                }
                Op::MulMulSub([a, b, c, e], d) => {
                    s[at(d)] = s[at(a)] * s[at(b)] - s[at(c)] * s[at(e)];
                }
                Op::MulMulMulAdd([a, b, c, e, f, g], d) => {
                    s[at(d)] = s[at(a)] * s[at(b)] + s[at(c)] * s[at(e)] + s[at(f)] * s[at(g)];
                }
                // Every other operation by name, not `_`: a match over all of the enum's
                // values needs no range check before its jump table.
                other @ (Op::Math1(..)
                | Op::Math2(..)
                | Op::Select3(..)
                | Op::Select4(..)
                | Op::Call(..)
                | Op::Internal(..)
                | Op::Pattern(..)
                | Op::Pigment(..)
                | Op::Spline(..)
                | Op::Sum(..)
                | Op::Prod(..)) => {
                    if OTHERS {
                        self.exec(other, &mut s, args);
                    }
                }
            }
        }
        s[at(self.result)]
    }

    /// The operations other than arithmetic.
    #[inline(never)]
    fn exec<const N: usize>(&self, op: Op, s: &mut [f64; N], args: &[f64]) {
        let g = |s: &[f64; N], i: u8| s[usize::from(i) & (N - 1)];
        let w = |s: &mut [f64; N], i: u8, v: f64| s[usize::from(i) & (N - 1)] = v;
        debug_assert!(!op.is_arithmetic(), "arithmetic runs in `run`");
        match op {
            Op::Math1(f, a, d) => w(s, d, math1(f, g(s, a))),
            Op::Math2(f, a, b, d) => w(s, d, math2(f, g(s, a), g(s, b))),
            Op::Select3([a, b, c], d) => {
                let v = if g(s, a) < 0.0 { g(s, b) } else { g(s, c) };
                w(s, d, v);
            }
            Op::Select4([a, b, c, e], d) => {
                let x = g(s, a);
                let v = if x < 0.0 {
                    g(s, b)
                } else if x == 0.0 {
                    g(s, c)
                } else {
                    g(s, e)
                };
                w(s, d, v);
            }
            Op::Call(i, a, d) => {
                let callee = &self.calls[i as usize];
                let a = usize::from(a);
                let v = callee.eval(&s[a..a + usize::from(callee.arity)]);
                w(s, d, v);
            }
            Op::Internal(f, a, n, d) => {
                let a = usize::from(a);
                let v = f.eval(&s[a..a + usize::from(n)]);
                w(s, d, v);
            }
            Op::Pattern(i, a, d) => {
                let (t, pattern) = &self.patterns[i as usize];
                let p = point(s, a);
                let v = crate::appearance::pattern::pattern_value(pattern, t.inverse_point(p));
                w(s, d, v);
            }
            Op::Pigment(i, ch, a, d) => {
                let v = channel(&self.pigments[i as usize], point(s, a), ch);
                w(s, d, v);
            }
            Op::Spline(i, c, a, d) => {
                let v = self.splines[i as usize].at(g(s, a), None);
                w(s, d, v[usize::from(c).min(4)]);
            }
            Op::Sum(i, a, b, d) => w(s, d, self.fold(i, args, (g(s, a), g(s, b)), false)),
            Op::Prod(i, a, b, d) => w(s, d, self.fold(i, args, (g(s, a), g(s, b)), true)),
            _ => {}
        }
    }

    fn fold(&self, callee: u32, args: &[f64], (from, to): (f64, f64), product: bool) -> f64 {
        let body = &self.calls[callee as usize];
        let mut inner = [0.0; MAX_PARAMS + 1];
        let n = args.len().min(MAX_PARAMS);
        inner[..n].copy_from_slice(&args[..n]);
        let mut acc = if product { 1.0 } else { 0.0 };
        let mut i = from;
        // POV-Ray steps by 1 from the start while the counter is at most the end.
        let mut steps = 0u32;
        while i <= to && steps < MAX_FOLD_STEPS {
            inner[n] = i;
            let v = body.eval(&inner[..=n]);
            acc = if product { acc * v } else { acc + v };
            i += 1.0;
            steps += 1;
        }
        acc
    }
}

fn point(s: &[f64], a: u8) -> DVec3 {
    let a = usize::from(a);
    DVec3::new(s[a], s[a + 1], s[a + 2])
}

/// Bounds a `sum`/`prod` whose end is huge or not finite, so a render cannot hang on it.
const MAX_FOLD_STEPS: u32 = 1 << 20;

fn channel(pigment: &Pigment, p: DVec3, ch: Channel) -> f64 {
    let c = crate::appearance::pigment::evaluate_pigment(pigment, p);
    match ch {
        Channel::Red => c.rgb.x,
        Channel::Green => c.rgb.y,
        Channel::Blue => c.rgb.z,
        Channel::Filter => c.filter,
        Channel::Transmit => c.transmit,
        Channel::Gray => 0.297 * c.rgb.x + 0.589 * c.rgb.y + 0.114 * c.rgb.z,
    }
}

fn math1(f: Math1, a: f64) -> f64 {
    match f {
        Math1::Abs => a.abs(),
        Math1::Acos => a.acos(),
        Math1::Acosh => a.acosh(),
        Math1::Asin => a.asin(),
        Math1::Asinh => a.asinh(),
        Math1::Atan => a.atan(),
        Math1::Atanh => a.atanh(),
        Math1::Ceil => a.ceil(),
        Math1::Cos => a.cos(),
        Math1::Cosh => a.cosh(),
        Math1::Degrees => a.to_degrees(),
        Math1::Exp => a.exp(),
        Math1::Floor => a.floor(),
        Math1::Int => a.trunc(),
        Math1::Ln => a.ln(),
        Math1::Log => a.log10(),
        Math1::Radians => a.to_radians(),
        Math1::Sin => a.sin(),
        Math1::Sinh => a.sinh(),
        Math1::Sqrt => a.sqrt(),
        Math1::Tan => a.tan(),
        Math1::Tanh => a.tanh(),
    }
}

fn math2(f: Math2, a: f64, b: f64) -> f64 {
    let truth = |t: bool| f64::from(u8::from(t));
    match f {
        Math2::Add => a + b,
        Math2::Sub => a - b,
        Math2::Mul => a * b,
        Math2::Div => a / b,
        Math2::Lt => truth(a < b),
        Math2::Le => truth(a <= b),
        Math2::Eq => truth(a == b),
        Math2::Ne => truth(a != b),
        Math2::Ge => truth(a >= b),
        Math2::Gt => truth(a > b),
        Math2::And => truth(a != 0.0 && b != 0.0),
        Math2::Or => truth(a != 0.0 || b != 0.0),
        Math2::Atan2 => a.atan2(b),
        Math2::Max => a.max(b),
        Math2::Min => a.min(b),
        Math2::Mod => a % b,
        Math2::Pow => a.powf(b),
    }
}

impl Math1 {
    /// The one table of names, for the parser and for error messages.
    pub const NAMES: &[(&str, Math1)] = &[
        ("abs", Math1::Abs),
        ("acos", Math1::Acos),
        ("acosh", Math1::Acosh),
        ("asin", Math1::Asin),
        ("asinh", Math1::Asinh),
        ("atan", Math1::Atan),
        ("atanh", Math1::Atanh),
        ("ceil", Math1::Ceil),
        ("cos", Math1::Cos),
        ("cosh", Math1::Cosh),
        ("degrees", Math1::Degrees),
        ("exp", Math1::Exp),
        ("floor", Math1::Floor),
        ("int", Math1::Int),
        ("ln", Math1::Ln),
        ("log", Math1::Log),
        ("radians", Math1::Radians),
        ("sin", Math1::Sin),
        ("sinh", Math1::Sinh),
        ("sqrt", Math1::Sqrt),
        ("tan", Math1::Tan),
        ("tanh", Math1::Tanh),
    ];

    pub fn named(name: &str) -> Option<Math1> {
        Self::NAMES.iter().find(|(n, _)| *n == name).map(|e| e.1)
    }
}

impl Math2 {
    /// Two-argument functions by name (`max` and `min` also take more, folded pairwise).
    pub fn named(name: &str) -> Option<Math2> {
        Some(match name {
            "atan2" => Math2::Atan2,
            "max" => Math2::Max,
            "min" => Math2::Min,
            "mod" => Math2::Mod,
            "pow" => Math2::Pow,
            _ => return None,
        })
    }
}

impl Channel {
    pub fn named(name: &str) -> Option<Channel> {
        Some(match name {
            "red" | "x" | "r" => Channel::Red,
            "green" | "y" | "g" => Channel::Green,
            "blue" | "z" | "b" => Channel::Blue,
            "filter" | "f" => Channel::Filter,
            "transmit" | "t" => Channel::Transmit,
            "gray" | "grey" => Channel::Gray,
            _ => return None,
        })
    }
}

#[cfg(test)]
mod compile_tests;
#[cfg(test)]
mod tests;
