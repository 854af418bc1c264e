//! Expected values are what POV-Ray 3.7.0.10 printed with `#debug concat(str(F(...), 0, 6))`
//! for the same declarations, with functions.inc included.

use std::sync::Arc;

use std::f64::consts::{FRAC_PI_2, PI};

use super::*;

fn arg(i: u8) -> Box<Expr> {
    Box::new(Expr::Arg(i))
}

fn c(v: f64) -> Box<Expr> {
    Box::new(Expr::Const(v))
}

fn internal(f: Internal, extra: &[f64]) -> Program {
    let mut args: Vec<Expr> = (0..3).map(Expr::Arg).collect();
    args.extend((0..extra.len()).map(|i| Expr::Arg(3 + i as u8)));
    compile(&Expr::Internal(f, args), 3 + extra.len()).unwrap()
}

fn at(p: &Program, args: &[f64]) -> f64 {
    p.eval(args)
}

#[test]
fn internal_functions_match_povray() {
    let close = |got: f64, want: f64| assert!((got - want).abs() < 5e-7, "{got} vs {want}");
    let sphere = internal(Internal::Sphere, &[0.0]);
    close(at(&sphere, &[1.0, 2.0, 2.0, 1.0]), 2.0);
    close(at(&sphere, &[0.0, 0.0, 0.0, 1.0]), -1.0);
    let torus = internal(Internal::Torus, &[0.0, 0.0]);
    close(at(&torus, &[3.0, 1.0, 0.0, 2.0, 0.5]), 0.914214);
    let rbox = internal(Internal::RoundedBox, &[0.0; 4]);
    close(at(&rbox, &[2.0, 0.5, 0.3, 0.1, 1.0, 1.0, 1.0]), 0.999999);
    close(at(&rbox, &[2.0, 2.0, 2.0, 0.1, 1.0, 1.0, 1.0]), 1.805255);
    close(at(&rbox, &[0.0, 0.0, 0.0, 0.1, 1.0, 0.5, 2.0]), -0.100001);
    close(at(&rbox, &[0.95, 0.0, 0.0, 0.1, 1.0, 0.5, 2.0]), -0.050001);
    close(at(&rbox, &[1.5, 0.2, 0.0, 0.1, 1.0, 0.5, 2.0]), 0.499999);
    close(at(&rbox, &[0.0, 0.0, 1.95, 0.1, 1.0, 0.5, 2.0]), -0.050001);
    let sell = internal(Internal::Superellipsoid, &[0.0; 2]);
    for (p, e, n, want) in [
        ([0.5, 0.5, 0.5], 0.5, 1.0, 0.223113),
        ([0.5, 0.5, 0.0], 1.0, 1.0, 0.292893),
        ([0.5, 0.5, 0.0], 0.5, 1.0, 0.405396),
        ([0.0, 0.5, 0.5], 0.5, 1.0, 0.292893),
        ([0.5, 0.0, 0.5], 1.0, 0.5, 0.405396),
        ([0.5, 0.5, 0.0], 1.0, 0.5, 0.292893),
        ([2.0, 0.0, 0.0], 1.0, 1.0, -1.0),
        ([0.0, 0.0, 0.0], 1.0, 1.0, 1.0),
    ] {
        close(at(&sell, &[p[0], p[1], p[2], e, n]), want);
    }
    close(at(&internal(Internal::R, &[]), &[1.0, 2.0, 2.0]), 3.0);
    let th = internal(Internal::Th, &[]);
    close(at(&th, &[1.0, 2.0, 3.0]), 0.321751);
    close(at(&th, &[-1.0, 0.0, 0.0]), -FRAC_PI_2);
    close(at(&th, &[0.0, 1.0, -1.0]), PI);
    let ph = internal(Internal::Ph, &[]);
    close(at(&ph, &[1.0, 2.0, 3.0]), 1.006854);
    close(at(&ph, &[1.0, 0.0, 0.0]), FRAC_PI_2);
    let ell = internal(Internal::Ellipsoid, &[0.0; 3]);
    close(at(&ell, &[1.0, 2.0, 3.0, 1.0, 2.0, 3.0]), 9.899495);
    close(at(&ell, &[1.0, 0.0, 0.0, 2.0, 1.0, 1.0]), 2.0);
}

#[test]
fn operators_follow_povray() {
    // select(x, 6, 5): 5 for x = 1, 6 for x = -1.
    let sel = compile(&Expr::Select(vec![Expr::Arg(0), *c(6.0), *c(5.0)]), 3).unwrap();
    assert_eq!(sel.eval(&[1.0, 0.0, 0.0]), 5.0);
    assert_eq!(sel.eval(&[-1.0, 0.0, 0.0]), 6.0);
    let sel4 = compile(
        &Expr::Select(vec![Expr::Arg(0), *c(1.0), *c(2.0), *c(3.0)]),
        1,
    )
    .unwrap();
    assert_eq!([-1.0, 0.0, 1.0].map(|a| sel4.eval(&[a])), [1.0, 2.0, 3.0]);
    // (x & y) + 10 (x | y) + 1000 (x = y): 10 at (1, 0), 1011 at (0.5, 0.5).
    let m = |f, a, b| Box::new(Expr::Math2(f, a, b));
    let logic = m(
        Math2::Add,
        m(
            Math2::Add,
            m(Math2::And, arg(0), arg(1)),
            m(Math2::Mul, c(10.0), m(Math2::Or, arg(0), arg(1))),
        ),
        m(Math2::Mul, c(1000.0), m(Math2::Eq, arg(0), arg(1))),
    );
    let logic = compile(&logic, 3).unwrap();
    assert_eq!(logic.eval(&[1.0, 0.0, 0.0]), 10.0);
    assert_eq!(logic.eval(&[0.5, 0.5, 0.0]), 1011.0);
    // mod(x, 3) + 10 int(y) + 100 floor(z) at (-4, -1.5, -1.5): -211.
    let md = m(
        Math2::Add,
        m(
            Math2::Add,
            m(Math2::Mod, arg(0), c(3.0)),
            m(
                Math2::Mul,
                c(10.0),
                Box::new(Expr::Math1(Math1::Int, arg(1))),
            ),
        ),
        m(
            Math2::Mul,
            c(100.0),
            Box::new(Expr::Math1(Math1::Floor, arg(2))),
        ),
    );
    assert_eq!(compile(&md, 3).unwrap().eval(&[-4.0, -1.5, -1.5]), -211.0);
}

#[test]
fn sums_products_and_calls() {
    // sum(i, 1, x, i*i) at 3: 14; prod(i, 1, x, i) at 4: 24.
    let fold = |product, body| Expr::Fold {
        product,
        from: c(1.0),
        to: arg(0),
        body,
    };
    let square = Box::new(Expr::Math2(Math2::Mul, arg(3), arg(3)));
    assert_eq!(
        compile(&fold(false, square), 3)
            .unwrap()
            .eval(&[3.0, 0.0, 0.0]),
        14.0
    );
    assert_eq!(
        compile(&fold(true, arg(3)), 3)
            .unwrap()
            .eval(&[4.0, 0.0, 0.0]),
        24.0
    );
    // G(a, b) = select(a, 1, 2, 3) + b; H = G(x, y) * 2 gives 8 at (1, 1, 0).
    let g = compile(
        &Expr::Math2(
            Math2::Add,
            Box::new(Expr::Select(vec![Expr::Arg(0), *c(1.0), *c(2.0), *c(3.0)])),
            arg(1),
        ),
        2,
    )
    .unwrap();
    let h = Expr::Math2(
        Math2::Mul,
        Box::new(Expr::Call(Arc::new(g), vec![Expr::Arg(0), Expr::Arg(1)])),
        c(2.0),
    );
    assert_eq!(compile(&h, 3).unwrap().eval(&[1.0, 1.0, 0.0]), 8.0);
}

#[test]
fn constants_fold_and_depth_is_bounded() {
    let e = Expr::Math2(
        Math2::Add,
        arg(0),
        Box::new(Expr::Math1(Math1::Sqrt, c(4.0))),
    );
    let p = compile(&e, 1).unwrap();
    assert_eq!(
        p.code.len(),
        1,
        "sqrt(4) folds to one constant: one addition is left"
    );
    assert_eq!(p.eval(&[1.5]), 3.5);
    // (x + (x + (x + ...))) with the nesting on the left holds one temporary per level.
    let mut deep = Expr::Arg(0);
    for _ in 0..MAX_SLOTS {
        deep = Expr::Math2(
            Math2::Add,
            Box::new(Expr::Math1(Math1::Abs, arg(0))),
            Box::new(deep),
        );
    }
    assert_eq!(compile(&deep, 1), Err(CompileError::TooDeep));
    assert_eq!(
        compile(&Expr::Arg(0), MAX_PARAMS + 1),
        Err(CompileError::TooManyParameters)
    );
}
