//! Built-in functions: one table says which names are functions, how many arguments each
//! takes and how it evaluates, so the evaluator's "is this a function?" and the call itself
//! cannot disagree. Functions POV-Ray has but penumbra cannot evaluate are listed too, so
//! they are reported as unsupported rather than unknown.

use std::rc::Rc;

use glam::{DMat3, DVec3};

use super::Evaluator;
use super::value::{Value, Vector};
use crate::lang::diagnostics::{Diagnostic, Span};
use crate::scene::Transform;

type R<T> = Result<T, Diagnostic>;

/// How many arguments a function takes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Arity {
    Exactly(usize),
    /// `select`: two outcomes (negative, otherwise) or three (negative, zero, positive).
    ThreeOrFour,
    AtLeastOne,
    /// The bitwise functions; as `AtLeastOne`, but POV-Ray's wording of the error differs
    /// and the scenes' diagnostics are kept as they were.
    SomeArguments,
    Any,
}

/// A call's evaluated arguments, with the call's name and span for its errors.
pub struct Call<'a> {
    pub name: &'a str,
    pub args: &'a [(Value, Span)],
    pub span: Span,
}

pub(super) type Native = fn(&mut Evaluator<'_>, &Call<'_>) -> R<Value>;

/// What a call does once its arguments are read and counted.
#[derive(Clone, Copy)]
pub enum Eval {
    /// A float to a float.
    Float(fn(f64) -> f64),
    Native(Native),
    /// `defined(Name)`: the argument is a name, read without evaluating it.
    Defined,
    /// POV-Ray has it; it needs parts of the model penumbra lacks.
    Unsupported,
}

pub struct Builtin {
    pub name: &'static str,
    pub arity: Arity,
    pub eval: Eval,
}

const fn float(name: &'static str, f: fn(f64) -> f64) -> Builtin {
    Builtin {
        name,
        arity: Arity::Exactly(1),
        eval: Eval::Float(f),
    }
}

const fn native(name: &'static str, arity: Arity, f: Native) -> Builtin {
    Builtin {
        name,
        arity,
        eval: Eval::Native(f),
    }
}

const fn unsupported(name: &'static str) -> Builtin {
    Builtin {
        name,
        arity: Arity::Any,
        eval: Eval::Unsupported,
    }
}

use Arity::{Exactly, ThreeOrFour};

/// Sorted by name, so lookups can search it (a test checks the order).
pub const BUILTINS: &[Builtin] = &[
    float("abs", f64::abs),
    float("acos", f64::acos),
    float("acosh", f64::acosh),
    native("asc", Exactly(1), asc),
    float("asin", f64::asin),
    float("asinh", f64::asinh),
    float("atan", f64::atan),
    native("atan2", Exactly(2), |ev, c| {
        Ok(Value::Float(f64::atan2(ev.arg_f(c, 0)?, ev.arg_f(c, 1)?)))
    }),
    float("atanh", f64::atanh),
    native("bitwise_and", Arity::SomeArguments, |ev, c| {
        bits(ev, c, |a, b| a & b)
    }),
    native("bitwise_or", Arity::SomeArguments, |ev, c| {
        bits(ev, c, |a, b| a | b)
    }),
    native("bitwise_xor", Arity::SomeArguments, |ev, c| {
        bits(ev, c, |a, b| a ^ b)
    }),
    float("ceil", f64::ceil),
    native("chr", Exactly(1), chr),
    native("concat", Arity::Any, concat),
    float("cos", f64::cos),
    float("cosh", f64::cosh),
    unsupported("datetime"),
    Builtin {
        name: "defined",
        arity: Exactly(1),
        eval: Eval::Defined,
    },
    float("degrees", f64::to_degrees),
    native("dimension_size", Exactly(2), dimension_size),
    native("dimensions", Exactly(1), dimensions),
    native("div", Exactly(2), |ev, c| {
        divide(ev, c, |a, b| (a / b).trunc())
    }),
    float("exp", f64::exp),
    native("file_exists", Exactly(1), file_exists),
    float("floor", f64::floor),
    unsupported("function"),
    native("inside", Exactly(2), super::placement::inside),
    float("int", f64::trunc),
    float("ln", f64::ln),
    float("log", f64::log10),
    native("max", Arity::AtLeastOne, |ev, c| fold(ev, c, f64::max)),
    native("max_extent", Exactly(1), super::placement::max_extent),
    native("min", Arity::AtLeastOne, |ev, c| fold(ev, c, f64::min)),
    native("min_extent", Exactly(1), super::placement::min_extent),
    native("mod", Exactly(2), |ev, c| divide(ev, c, |a, b| a % b)),
    unsupported("now"),
    native("pow", Exactly(2), |ev, c| {
        Ok(Value::Float(f64::powf(ev.arg_f(c, 0)?, ev.arg_f(c, 1)?)))
    }),
    unsupported("prod"),
    float("radians", f64::to_radians),
    native("rand", Exactly(1), rand),
    native("seed", Exactly(1), seed),
    native("select", ThreeOrFour, select),
    float("sin", f64::sin),
    float("sinh", f64::sinh),
    unsupported("spline"),
    float("sqr", |x| x * x),
    float("sqrt", f64::sqrt),
    native("str", Exactly(3), |ev, c| {
        let s = format_float(ev.arg_f(c, 0)?, ev.arg_f(c, 1)?, ev.arg_f(c, 2)?);
        Ok(Value::Str(Rc::from(s)))
    }),
    native("strcmp", Exactly(2), strcmp),
    native("strlen", Exactly(1), |ev, c| {
        Ok(Value::Float(ev.arg_s(c, 0)?.chars().count() as f64))
    }),
    native("strlwr", Exactly(1), |ev, c| {
        Ok(Value::Str(Rc::from(ev.arg_s(c, 0)?.to_lowercase())))
    }),
    native("strupr", Exactly(1), |ev, c| {
        Ok(Value::Str(Rc::from(ev.arg_s(c, 0)?.to_uppercase())))
    }),
    native("substr", Exactly(3), substr),
    unsupported("sum"),
    float("tan", f64::tan),
    float("tanh", f64::tanh),
    native("trace", ThreeOrFour, super::placement::trace),
    native("val", Exactly(1), |ev, c| {
        Ok(Value::Float(
            ev.arg_s(c, 0)?.trim().parse::<f64>().unwrap_or(0.0),
        ))
    }),
    native("vaxis_rotate", Exactly(3), vaxis_rotate),
    native("vcross", Exactly(2), |ev, c| {
        Ok(Value::Vector(Vector::new3(
            ev.arg_v(c, 0)?.cross(ev.arg_v(c, 1)?),
        )))
    }),
    native("vdot", Exactly(2), |ev, c| {
        Ok(Value::Float(ev.arg_v(c, 0)?.dot(ev.arg_v(c, 1)?)))
    }),
    native("vlength", Exactly(1), vlength),
    native("vnormalize", Exactly(1), vnormalize),
    native("vrotate", Exactly(2), |ev, c| {
        let v = Transform::rotate(ev.arg_v(c, 1)?).vector(ev.arg_v(c, 0)?);
        Ok(Value::Vector(Vector::new3(v)))
    }),
    native("vstr", Exactly(5), vstr),
    native("vturbulence", Exactly(4), vturbulence),
];

/// `vturbulence(lambda, omega, octaves, p)`: the displacement `warp { turbulence 1 }`
/// with those settings gives p (the same sum, so the two agree exactly).
fn vturbulence(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let t = crate::scene::Turbulence {
        amount: glam::DVec3::ONE,
        lambda: ev.arg_f(c, 0)?,
        omega: ev.arg_f(c, 1)?,
        octaves: ev.arg_f(c, 2)?.clamp(1.0, 10.0) as u32,
    };
    let d = crate::appearance::noise::dturbulence(ev.arg_v(c, 3)?, &t);
    Ok(Value::Vector(Vector::new3(d)))
}

/// POV-Ray 3.7's built-in identifiers that are not functions (its documentation's float,
/// vector and string identifiers), for the table in docs/language.md.
pub const IDENTIFIERS: &[&str] = &[
    "clock",
    "clock_delta",
    "clock_on",
    "false",
    "final_clock",
    "final_frame",
    "frame_number",
    "image_height",
    "image_width",
    "initial_clock",
    "initial_frame",
    "input_file_name",
    "no",
    "off",
    "on",
    "pi",
    "t",
    "true",
    "u",
    "v",
    "version",
    "x",
    "y",
    "yes",
    "z",
];

/// The markdown table of every POV-Ray 3.7 built-in function and identifier with whether
/// penumbra evaluates it, made from the tables above and the evaluator's own list of
/// expression keywords: docs/language.md holds a copy, and a test keeps the two equal.
pub fn builtins_markdown() -> String {
    let mut rows: Vec<(&str, &str, bool)> = BUILTINS
        .iter()
        .map(|b| (b.name, "function", b.is_supported()))
        .chain(IDENTIFIERS.iter().map(|&name| {
            (
                name,
                "identifier",
                super::keywords::is_expression_keyword(name),
            )
        }))
        .collect();
    rows.sort_by_key(|r| r.0);
    let mut out = String::from("| built-in | kind | penumbra |\n| --- | --- | --- |\n");
    for (name, kind, supported) in rows {
        let status = if supported {
            "supported"
        } else {
            "not supported"
        };
        out += &format!("| `{name}` | {kind} | {status} |\n");
    }
    out
}

/// The table's entry for `name`, supported or not.
pub fn builtin(name: &str) -> Option<&'static Builtin> {
    BUILTINS
        .binary_search_by(|b| b.name.cmp(name))
        .ok()
        .map(|i| &BUILTINS[i])
}

impl Builtin {
    pub fn is_supported(&self) -> bool {
        !matches!(self.eval, Eval::Unsupported)
    }
}

impl Evaluator<'_> {
    /// Checks the argument count, then evaluates; `defined` never gets here (its argument
    /// is not an expression).
    pub(super) fn apply_builtin(&mut self, b: &Builtin, call: &Call<'_>) -> R<Value> {
        self.check_arity(b.arity, call)?;
        match b.eval {
            Eval::Float(f) => Ok(Value::Float(f(self.arg_f(call, 0)?))),
            Eval::Native(f) => f(self, call),
            Eval::Defined | Eval::Unsupported => Err(self.err(
                call.span,
                format!("unsupported: `{}` is not supported yet", call.name),
            )),
        }
    }

    pub(super) fn check_arity(&self, arity: Arity, call: &Call<'_>) -> R<()> {
        let (name, found) = (call.name, call.args.len());
        let message = match arity {
            Exactly(n) if found != n => format!(
                "`{name}` takes {n} argument{}, found {found}",
                if n == 1 { "" } else { "s" }
            ),
            ThreeOrFour if found != 3 && found != 4 => format!("`{name}` takes 3 or 4 arguments"),
            Arity::AtLeastOne if found == 0 => format!("`{name}` needs at least one argument"),
            Arity::SomeArguments if found == 0 => format!("`{name}` needs arguments"),
            _ => return Ok(()),
        };
        Err(self.err(call.span, message))
    }

    fn arg_f(&self, call: &Call<'_>, i: usize) -> R<f64> {
        let (v, span) = &call.args[i];
        self.to_float(v, *span)
    }

    fn arg_v(&self, call: &Call<'_>, i: usize) -> R<DVec3> {
        let (v, span) = &call.args[i];
        self.to_vec3(v, *span)
    }

    fn arg_s(&self, call: &Call<'_>, i: usize) -> R<Rc<str>> {
        match &call.args[i] {
            (Value::Str(s), _) => Ok(s.clone()),
            (other, span) => Err(self.err(
                *span,
                format!("expected a string, found {}", other.kind_name()),
            )),
        }
    }

    fn arg_array_dims(&self, call: &Call<'_>, i: usize) -> R<Vec<usize>> {
        match &call.args[i] {
            (Value::Array(a), _) => Ok(a.borrow().dims.clone()),
            (other, span) => Err(self.err(
                *span,
                format!("expected an array, found {}", other.kind_name()),
            )),
        }
    }
}

/// `mod` and `div`: a zero divisor is an error at the divisor, not a NaN in the scene.
fn divide(ev: &mut Evaluator<'_>, c: &Call<'_>, op: fn(f64, f64) -> f64) -> R<Value> {
    let (a, b) = (ev.arg_f(c, 0)?, ev.arg_f(c, 1)?);
    if b == 0.0 {
        return Err(ev.err(c.args[1].1, "division by zero"));
    }
    Ok(Value::Float(op(a, b)))
}

fn fold(ev: &mut Evaluator<'_>, c: &Call<'_>, op: fn(f64, f64) -> f64) -> R<Value> {
    let mut m = ev.arg_f(c, 0)?;
    for i in 1..c.args.len() {
        m = op(m, ev.arg_f(c, i)?);
    }
    Ok(Value::Float(m))
}

/// The bitwise functions work on the arguments truncated to integers.
fn bits(ev: &mut Evaluator<'_>, c: &Call<'_>, op: fn(i64, i64) -> i64) -> R<Value> {
    let mut acc = ev.arg_f(c, 0)? as i64;
    for i in 1..c.args.len() {
        acc = op(acc, ev.arg_f(c, i)? as i64);
    }
    Ok(Value::Float(acc as f64))
}

fn select(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let cond = ev.arg_f(c, 0)?;
    let pick = if cond < 0.0 {
        1
    } else if c.args.len() == 3 || cond == 0.0 {
        2
    } else {
        3
    };
    Ok(c.args[pick].0.clone())
}

fn vlength(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    // A 2-, 4- or 5-vector's own length; a float or colour counts as its 3-vector.
    let own = vector_len(&c.args[0].0);
    let promoted = ev.arg_v(c, 0)?.length();
    Ok(Value::Float(own.unwrap_or(promoted)))
}

fn vnormalize(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let v = ev.arg_v(c, 0)?;
    let l = v.length();
    if l == 0.0 {
        return Err(ev.err(c.args[0].1, "cannot normalize a zero-length vector"));
    }
    Ok(Value::Vector(Vector::new3(v / l)))
}

fn vaxis_rotate(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let axis = ev.arg_v(c, 1)?;
    if axis.length() == 0.0 {
        return Err(ev.err(c.args[1].1, "the rotation axis has zero length"));
    }
    let m = DMat3::from_axis_angle(axis.normalize(), ev.arg_f(c, 2)?.to_radians());
    Ok(Value::Vector(Vector::new3(m * ev.arg_v(c, 0)?)))
}

fn vstr(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let (v, len) = match &c.args[1].0 {
        Value::Vector(v) => (v.c, v.len as usize),
        Value::Colour(c) => (*c, 5),
        Value::Float(x) => ([*x; 5], 5),
        other => {
            return Err(ev.err(
                c.args[1].1,
                format!("expected a vector, found {}", other.kind_name()),
            ));
        }
    };
    let n = (ev.arg_f(c, 0)?.max(0.0) as usize).min(len).min(5);
    let sep = ev.arg_s(c, 2)?;
    let (l, p) = (ev.arg_f(c, 3)?, ev.arg_f(c, 4)?);
    let parts: Vec<String> = v[..n].iter().map(|x| format_float(*x, l, p)).collect();
    Ok(Value::Str(Rc::from(parts.join(&sep))))
}

fn concat(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let mut out = String::new();
    for i in 0..c.args.len() {
        out.push_str(&ev.arg_s(c, i)?);
    }
    Ok(Value::Str(Rc::from(out)))
}

fn chr(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let ch = char::from_u32(ev.arg_f(c, 0)?.max(0.0) as u32).unwrap_or('?');
    Ok(Value::Str(Rc::from(ch.to_string())))
}

fn asc(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let first = ev.arg_s(c, 0)?.chars().next();
    Ok(Value::Float(first.map_or(0.0, |ch| f64::from(ch as u32))))
}

fn substr(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let t: Vec<char> = ev.arg_s(c, 0)?.chars().collect();
    let start = ev.arg_f(c, 1)? as i64 - 1;
    let len = ev.arg_f(c, 2)? as i64;
    if start < 0 || len < 0 || start.saturating_add(len) as usize > t.len() {
        return Err(ev.err(c.span, "`substr` range is outside the string"));
    }
    let out: String = t[start as usize..(start + len) as usize].iter().collect();
    Ok(Value::Str(Rc::from(out)))
}

fn strcmp(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    Ok(Value::Float(match ev.arg_s(c, 0)?.cmp(&ev.arg_s(c, 1)?) {
        std::cmp::Ordering::Less => -1.0,
        std::cmp::Ordering::Equal => 0.0,
        std::cmp::Ordering::Greater => 1.0,
    }))
}

fn file_exists(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let name = ev.arg_s(c, 0)?;
    Ok(Value::Float(f64::from(u8::from(
        ev.resolve_include(&name).is_some(),
    ))))
}

fn dimensions(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    Ok(Value::Float(ev.arg_array_dims(c, 0)?.len() as f64))
}

fn dimension_size(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let dims = ev.arg_array_dims(c, 0)?;
    let n = ev.arg_f(c, 1)?;
    // POV-Ray counts dimensions from 1.
    if n < 1.0 || n as usize > dims.len() {
        return Err(ev.err(
            c.args[1].1,
            format!(
                "this array has {} dimensions, asked for dimension {n}",
                dims.len()
            ),
        ));
    }
    Ok(Value::Float(dims[n as usize - 1] as f64))
}

fn seed(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let seed = ev.arg_f(c, 0)?;
    if ev.rng_states.len() >= MAX_RANDOM_STREAMS {
        return Err(ev.err(
            c.span,
            format!("too many random streams (more than {MAX_RANDOM_STREAMS})"),
        ));
    }
    ev.rng_states.push(u64::from(seed_state(seed)));
    Ok(Value::Float((ev.rng_states.len() - 1) as f64))
}

fn rand(ev: &mut Evaluator<'_>, c: &Call<'_>) -> R<Value> {
    let i = ev.arg_f(c, 0)?;
    let state = if i >= 0.0 {
        ev.rng_states.get_mut(i as usize)
    } else {
        None
    };
    let Some(state) = state else {
        return Err(ev.err(c.args[0].1, "`rand` needs a stream made by `seed`"));
    };
    Ok(Value::Float(next_random(state)))
}

fn vector_len(v: &Value) -> Option<f64> {
    match v {
        Value::Vector(v) => Some(
            v.c[..v.len as usize]
                .iter()
                .map(|x| x * x)
                .sum::<f64>()
                .sqrt(),
        ),
        _ => None,
    }
}

/// `str(value, length, precision)`: at least `length` characters (negative: pad with
/// zeros), `precision` decimals (negative: 6).
fn format_float(x: f64, len: f64, prec: f64) -> String {
    let prec = if prec < 0.0 {
        6
    } else {
        prec.min(20.0) as usize
    };
    let width = len.abs().min(64.0) as usize;
    if len < 0.0 {
        format!("{x:0width$.prec$}")
    } else {
        format!("{x:width$.prec$}")
    }
}

/// `seed(n)` streams a scene may make; scenes make a handful, a loop making millions is a
/// mistake that would otherwise only end when memory does.
const MAX_RANDOM_STREAMS: usize = 1_000_000;

/// The 32-bit state `seed(n)` starts from. Measured from POV-Ray 3.7's `#debug` output: the
/// float is truncated to a 32-bit integer, and out-of-range values (and NaN) become
/// 0x8000_0000, as the x86 conversion instruction gives.
fn seed_state(n: f64) -> u32 {
    if n.is_finite() && n > -2_147_483_649.0 && n < 2_147_483_648.0 {
        n.trunc() as i32 as u32
    } else {
        0x8000_0000
    }
}

/// POV-Ray 3.7's `rand` sequence, reproduced because scenes place objects with it: a 32-bit
/// linear congruential step (multiplier 1812433253, increment 12345), the new state divided
/// by 2^32 - 1. Checked against the installed POV-Ray's `#debug` output for several seeds
/// (see the `rand_matches_povray` test).
fn next_random(state: &mut u64) -> f64 {
    let next = (*state as u32)
        .wrapping_mul(1_812_433_253)
        .wrapping_add(12_345);
    *state = u64::from(next);
    f64::from(next) / f64::from(u32::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lang::{LoadOptions, load_scene_source};

    const PRELUDE: &str =
        "#declare Arr = array[2] {1, 2}; #declare Obj = sphere { 0, 1 } #declare N = <0, 0, 0>;\n";

    fn run(call: &str) -> Result<(), Diagnostic> {
        let src = format!("{PRELUDE}#declare R = {call};\n");
        load_scene_source("test.pov", &src, &LoadOptions::default()).map(|_| ())
    }

    /// Arguments each function accepts; a function added to the table without a line here
    /// fails the test, so the table cannot grow untested.
    fn sample_args(name: &str) -> Option<&'static str> {
        Some(match name {
            "abs" | "acos" | "asin" | "atan" | "atanh" | "ceil" | "cos" | "cosh" | "degrees"
            | "exp" | "floor" | "int" | "ln" | "log" | "radians" | "sin" | "sinh" | "sqr"
            | "sqrt" | "tan" | "tanh" | "asinh" | "seed" => "0.5",
            "acosh" => "2",
            "asc" | "strlen" | "strlwr" | "strupr" => "\"aB\"",
            "atan2" | "bitwise_and" | "bitwise_or" | "bitwise_xor" | "div" | "mod" | "pow"
            | "max" | "min" => "6, 4",
            "chr" => "65",
            "concat" | "strcmp" => "\"a\", \"b\"",
            "defined" => "Arr",
            "dimension_size" => "Arr, 1",
            "dimensions" => "Arr",
            "file_exists" => "\"no such file.inc\"",
            "rand" => "seed(1)",
            "select" => "0, 1, 2, 3",
            "str" => "1, 0, 2",
            "substr" => "\"abc\", 2, 2",
            "val" => "\"1.5\"",
            "vaxis_rotate" => "x, y, 90",
            "vcross" | "vdot" => "x, y",
            "vlength" => "<1, 2>",
            "vnormalize" => "<1, 2, 3>",
            "vrotate" => "x, <0, 0, 90>",
            "vstr" => "3, <1, 2, 3>, \",\", 0, 1",
            "vturbulence" => "2, 0.5, 6, <1, 2, 3>",
            "inside" => "Obj, <0, 0, 0>",
            "max_extent" | "min_extent" => "Obj",
            "trace" => "Obj, <0, 0, -5>, z, N",
            _ => return None,
        })
    }

    /// docs/language.md's built-ins table is `builtins_markdown()` between two marker
    /// lines; `PENUMBRA_BLESS=1` rewrites it there.
    #[test]
    fn the_documented_builtins_table_matches_the_code() {
        const START: &str =
            "<!-- builtins table: generated by builtins_markdown(), do not edit -->\n";
        const END: &str = "<!-- end of builtins table -->";
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/language.md");
        let doc = std::fs::read_to_string(path).expect("docs/language.md");
        let start = doc.find(START).expect("the table's start marker") + START.len();
        let end = start + doc[start..].find(END).expect("the table's end marker");
        let table = builtins_markdown();
        if std::env::var_os("PENUMBRA_BLESS").is_some() {
            let fresh = format!("{}{table}{}", &doc[..start], &doc[end..]);
            std::fs::write(path, fresh).expect("write docs/language.md");
            return;
        }
        assert_eq!(
            doc[start..end],
            table,
            "run with PENUMBRA_BLESS=1 to regenerate"
        );
    }

    #[test]
    fn table_is_sorted_without_duplicates() {
        for pair in BUILTINS.windows(2) {
            assert!(
                pair[0].name < pair[1].name,
                "`{}` then `{}`: the table must be sorted, each name once",
                pair[0].name,
                pair[1].name
            );
        }
        assert!(BUILTINS.iter().all(|b| builtin(b.name).is_some()));
        assert!(builtin("sine").is_none());
    }

    /// Unknown names get their "did you mean" hint from the keyword list, and only
    /// keywords are reported as "unsupported" rather than "unknown".
    #[test]
    fn every_function_is_a_keyword() {
        for b in BUILTINS {
            assert!(super::super::keywords::is_keyword(b.name), "`{}`", b.name);
            assert_eq!(
                super::super::keywords::is_function(b.name),
                b.is_supported()
            );
        }
    }

    #[test]
    fn every_function_evaluates_with_its_arity() {
        for b in BUILTINS {
            let name = b.name;
            if !b.is_supported() {
                // Not in a `#declare`, which would keep the error for when the name is used.
                let src = format!("#if ({name}(1)) #end\n");
                let e = load_scene_source("test.pov", &src, &LoadOptions::default())
                    .map(|_| ())
                    .expect_err(name);
                assert_eq!(
                    e.message,
                    format!("unsupported: `{name}` is not supported yet")
                );
                continue;
            }
            let args = sample_args(name).unwrap_or_else(|| panic!("no sample for `{name}`"));
            if let Err(e) = run(&format!("{name}({args})")) {
                panic!("`{name}({args})`: {e}");
            }
        }
    }

    #[test]
    fn wrong_arity_is_an_error_at_the_call() {
        for b in BUILTINS
            .iter()
            .filter(|b| matches!(b.eval, Eval::Float(_) | Eval::Native(_)))
        {
            let name = b.name;
            let (args, message) = match b.arity {
                Exactly(n) => (
                    vec!["0"; n + 1].join(", "),
                    format!(
                        "`{name}` takes {n} argument{}, found {}",
                        if n == 1 { "" } else { "s" },
                        n + 1
                    ),
                ),
                ThreeOrFour => (
                    "0, 0".to_string(),
                    format!("`{name}` takes 3 or 4 arguments"),
                ),
                Arity::AtLeastOne => (
                    String::new(),
                    format!("`{name}` needs at least one argument"),
                ),
                Arity::SomeArguments => (String::new(), format!("`{name}` needs arguments")),
                Arity::Any => continue,
            };
            let call = format!("{name}({args})");
            let e = run(&call).expect_err(&call);
            assert_eq!(e.message, message);
            assert_eq!((e.line(), e.column()), (Some(2), Some(14)), "{call}");
            assert_eq!(
                e.location.as_ref().map(|l| l.width),
                Some(call.len()),
                "{call}"
            );
        }
    }
}
