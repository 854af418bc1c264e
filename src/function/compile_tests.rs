//! The compiler's fused operations and slot layout give what the plain expression gives.

use super::*;
use std::sync::Arc;

fn arg(i: u8) -> Box<Expr> {
    Box::new(Expr::Arg(i))
}

fn op(f: Math2, a: Box<Expr>, b: Box<Expr>) -> Box<Expr> {
    Box::new(Expr::Math2(f, a, b))
}

#[test]
fn sums_and_differences_of_two_products_are_fused_and_exact() {
    // x*y + z*w and x*y - z*w, with values whose products round.
    for f in [Math2::Add, Math2::Sub] {
        let e = op(
            f,
            op(Math2::Mul, arg(0), arg(1)),
            op(Math2::Mul, arg(2), arg(3)),
        );
        let p = compile(&e, 4).expect("compiles");
        assert_eq!(p.code.len(), 1, "{:?}", p.code);
        let (x, y, z, w) = (0.1, 0.7, 1.0 / 3.0, 2.0f64.sqrt());
        let want = if f == Math2::Add {
            x * y + z * w
        } else {
            x * y - z * w
        };
        assert_eq!(p.eval(&[x, y, z, w]).to_bits(), want.to_bits());
    }
}

#[test]
fn constants_keep_their_slots_when_called_with_x_y_z() {
    // A function of u, v (arity 2) read at a point: the third coordinate must not land on
    // the constant's slot.
    let e = op(Math2::Add, arg(0), Box::new(Expr::Const(5.0)));
    let p = compile(&e, 2).expect("compiles");
    assert_eq!(p.at(glam::DVec3::new(1.0, 2.0, 100.0)), 6.0);
    // And with exactly x, y, z for a function of three.
    let e = op(Math2::Mul, arg(2), Box::new(Expr::Const(0.5)));
    let p = compile(&e, 3).expect("compiles");
    assert_eq!(p.at(glam::DVec3::new(1.0, 2.0, 8.0)), 4.0);
}

#[test]
fn sums_of_three_products_are_fused_and_round_as_written() {
    // (x*y + z*w) + u*v, left to right as POV-Ray's parser groups it, in one operation.
    let e = op(
        Math2::Add,
        op(
            Math2::Add,
            op(Math2::Mul, arg(0), arg(1)),
            op(Math2::Mul, arg(2), arg(3)),
        ),
        op(Math2::Mul, arg(4), arg(5)),
    );
    let p = compile(&e, 6).expect("compiles");
    assert_eq!(p.code.len(), 1, "{:?}", p.code);
    assert!(p.arithmetic);
    let v = [0.1, 0.7, 1.0 / 3.0, 2.0f64.sqrt(), 1e-17, 3.0];
    let want = (v[0] * v[1] + v[2] * v[3]) + v[4] * v[5];
    assert_eq!(p.eval(&v).to_bits(), want.to_bits());
}

#[test]
fn programs_with_calls_run_in_the_general_loop() {
    // sqrt(x*x + y*y + z*z) is not pure arithmetic: it must still be computed.
    let squares = op(
        Math2::Add,
        op(
            Math2::Add,
            op(Math2::Mul, arg(0), arg(0)),
            op(Math2::Mul, arg(1), arg(1)),
        ),
        op(Math2::Mul, arg(2), arg(2)),
    );
    let e = Expr::Math1(Math1::Sqrt, squares);
    let p = compile(&e, 3).expect("compiles");
    assert!(!p.arithmetic);
    assert_eq!(p.at(glam::DVec3::new(2.0, 3.0, 6.0)), 7.0);
}

#[test]
fn a_call_of_a_declared_internal_function_is_the_internal_function() {
    // functions.inc's `f_rounded_box = function { internal(60) }`, called with x, y, z and
    // four constants: the call becomes the internal function's operation, with the value
    // the call gave, bit for bit; a function that does more than pass its arguments on
    // stays a call.
    let rounded_box = Internal::numbered(60).expect("internal 60");
    let n = rounded_box.arity() as u8;
    let wrapper = |args: Vec<Expr>| {
        Arc::new(compile(&Expr::Internal(rounded_box, args), n.into()).expect("compiles"))
    };
    let plain = wrapper((0..n).map(Expr::Arg).collect());
    let swapped = wrapper([1, 0].into_iter().chain(2..n).map(Expr::Arg).collect());
    assert_eq!(plain.wrapped_internal(), Some(rounded_box));
    assert_eq!(swapped.wrapped_internal(), None);
    let consts = [0.05, 0.5, 0.4, 0.3].map(Expr::Const);
    let call = |p: &Arc<Program>| {
        let args = (0..3)
            .map(Expr::Arg)
            .chain(consts.iter().cloned())
            .collect();
        compile(&Expr::Call(p.clone(), args), 3).expect("compiles")
    };
    let (direct, called) = (call(&plain), call(&swapped));
    assert!(direct.calls.is_empty() && called.calls.len() == 1);
    let mut next = crate::geometry::uniform_stream(0x7e57_ca11);
    for _ in 0..1000 {
        let p = glam::DVec3::new(next(), next(), next()) - 0.5;
        let want = rounded_box.eval(&[p.x, p.y, p.z, 0.05, 0.5, 0.4, 0.3]);
        assert_eq!(direct.at(p).to_bits(), want.to_bits(), "at {p}");
        let swapped_want = rounded_box.eval(&[p.y, p.x, p.z, 0.05, 0.5, 0.4, 0.3]);
        assert_eq!(called.at(p).to_bits(), swapped_want.to_bits(), "at {p}");
    }
}
