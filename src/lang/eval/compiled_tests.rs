//! Compiled expressions against the interpreter: the same scene read both ways must give
//! the same values, the same errors at the same places, and read on from the same token.

use proptest::prelude::*;

use super::super::Evaluator;
use crate::lang::MemoryFiles;

/// What reading `source` gives: the printed globals, or the error as Debug text.
fn outcome(source: &str, compile: bool, globals: &[&str]) -> (String, usize) {
    let files = MemoryFiles::default();
    let mut ev = Evaluator::new(&files, Vec::new(), 64, 48);
    ev.programs.disabled = !compile;
    let text = match ev.run("test.pov", source) {
        Ok(()) => globals
            .iter()
            .map(|g| format!("{g} = {:?}", ev.global(g)))
            .collect::<Vec<_>>()
            .join("; "),
        Err(d) => format!("error: {d:?}"),
    };
    let compiled = ev.programs.compiled();
    (text, compiled)
}

/// A loop that reads `expr` twice; with `retype`, `A` holds a vector on the second pass.
fn looped(expr: &str, retype: bool) -> String {
    let retype = if retype {
        "#if (I = 1) #declare A = <1, 2, 3>; #end"
    } else {
        ""
    };
    format!(
        "#declare A = 1.5; #declare B = -2; #declare C = 0; #declare S = seed(3);\n\
         #declare V = <1, 2, 3>; #declare W = <0.5, -1>;\n\
         #declare I = 0;\n\
         #while (I < 2)\n\
           {retype}\n\
           #declare R = {expr};\n\
           #if (I = 0) #declare R0 = R; #end\n\
           #declare After = I;\n\
           #declare I = I + 1;\n\
         #end\n\
         #declare Next = rand(S);\n"
    )
}

/// `Next` is the random stream's next value after the loop: a run that failed and was
/// read again by the interpreter must not have advanced it twice.
const GLOBALS: &[&str] = &["R0", "R", "After", "I", "Next"];

fn same_both_ways(expr: &str, retype: bool) -> usize {
    let source = looped(expr, retype);
    let (interpreted, none) = outcome(&source, false, GLOBALS);
    let (compiled, count) = outcome(&source, true, GLOBALS);
    assert_eq!(none, 0);
    assert_eq!(compiled, interpreted, "{expr}");
    count
}

/// Expressions of every compiled operation give the interpreter's values, and are compiled.
#[test]
fn each_operation_compiles_to_the_interpreters_value() {
    let cases = [
        "A + B * 2 - C / 4",
        "(A < B) + (A <= 1.5) + (A = 1.5) + (A != B) + (A >= 2) + (A > B)",
        "(A & C) + (A | C) + !C + -A + +B",
        "<A, B, A * B>",
        "<A B C>",
        "<1, 2, 3,>",
        "V * 2 + W",
        "-V / A",
        "V.x + V.y * V.z + W.u + W.v + x.x + t.t",
        "(A > 0 ? V : -V)",
        "<(B < 0 ? 1 : 2), pi, 0>",
        "((A + B) * (A - B))",
        "(V + <1, 1, 1>).z",
        "<A, B, C, A, B>",
        "sqrt(sin(A) * 2) + int(B / 3) + degrees(pi)",
        "<cos(A), 1, abs(B)>",
        "mod(A * 7, 3) + pow(A, 2) + max(A, B, C) + min(1, 2) + atan2(A, B) + div(7, 2)",
        "bitwise_and(7, 3) + bitwise_or(4, 1) + bitwise_xor(5, 1)",
        "<vlength(V), vdot(V, W), vlength(W)> + vcross(V, x) + vnormalize(V) + vrotate(V, <0, 90, 0>)",
        "vaxis_rotate(V, y, 30) * A",
        "rand(S) * 10 + A",
        "<rand(S), rand(S), rand(S)>",
    ];
    // The loop's own expressions (`I < 2`, `I = 0`, `I + 1`); a lone `0` is not compiled.
    let base = same_both_ways("0", false);
    assert_eq!(base, 3);
    for expr in cases {
        let count = same_both_ways(expr, false);
        assert!(count > base, "{expr} did not compile");
    }
}

/// A name that changes kind between passes, a division by zero, an unknown name and a
/// directive inside the expression all leave the expression to the interpreter, with its
/// value or error.
#[test]
fn what_does_not_compile_reads_as_before() {
    for expr in [
        "A * 2 + 1",
        "<A, 1, 2>",
        "A < 2",
        "rand(S) + A",
        "<rand(S), A, 1>",
    ] {
        same_both_ways(expr, true);
    }
    for expr in [
        "A / C",
        "<A, B / (C * 2), 1>",
        "A + Q",
        "V < 2",
        "V.q",
        "<1>",
        "<1, 2, 3, 4, 5, 6>",
        "A ? 1 : 2",
        "A + #if (I = 0) 1 #else 2 #end",
        "\"text\"",
        "rgb <1, 0, 0>",
        "sin(V)",
        "sin(A, B)",
        "sin()",
        "sin A",
        "mod(A, C)",
        "rand(S) + rand(S) / C",
        "rand(S) + Q",
        "rand(A)",
        "vnormalize(<0, 0, 0>) + rand(S)",
        "pow(V, 2)",
        "max()",
        "select(A, 1, 2)",
        "seed(2) + 1",
    ] {
        same_both_ways(expr, false);
    }
}

/// Nesting deeper than the compiler takes is read by the interpreter, whose limit then
/// gives its error.
#[test]
fn deep_nesting_keeps_the_interpreters_limit() {
    for depth in [10, 40, 300] {
        let expr = format!("{}A{}", "(".repeat(depth), " + 1)".repeat(depth));
        same_both_ways(&expr, false);
    }
}

/// A macro's body is compiled too, and an expression continuing past the macro's end (its
/// value used by the caller) is left to the interpreter.
#[test]
fn macro_bodies_compile_and_their_ends_stay_interpreted() {
    let source = "#macro Twice(X) #local Y = X * 2 + 1; (Y) #end\n\
                  #macro Half(X) X / 2 #end\n\
                  #declare S = 0;\n\
                  #declare I = 0;\n\
                  #while (I < 5)\n\
                    #declare S = S + Twice(I) + Half(I) * 3;\n\
                    #declare I = I + 1;\n\
                  #end\n";
    let (interpreted, _) = outcome(source, false, &["S", "I"]);
    let (compiled, count) = outcome(source, true, &["S", "I"]);
    assert_eq!(compiled, interpreted);
    // Twice: 2 * 10 + 5; Half continued by the caller: (0 + 1 + 2 + 3 + 4) / 2 * 3.
    assert!(interpreted.contains("Float(40.0)"), "{interpreted}");
    assert!(count >= 3, "{count}");
}

fn leaf() -> impl Strategy<Value = String> {
    prop::sample::select(vec![
        "0", "1", "2.5", "A", "B", "C", "V", "W", "Q", "pi", "x", "t", "u", "rand(S)",
    ])
    .prop_map(String::from)
}

fn expression() -> impl Strategy<Value = String> {
    leaf().prop_recursive(5, 24, 3, |inner| {
        let op = prop::sample::select(vec![
            "+", "-", "*", "/", "<", "<=", "=", "!=", ">=", ">", "&", "|",
        ]);
        let field = prop::sample::select(vec!["x", "y", "t", "u", "gray", "q"]);
        prop_oneof![
            (inner.clone(), op, inner.clone()).prop_map(|(a, o, b)| format!("{a} {o} {b}")),
            (prop::sample::select(vec!["-", "+", "!"]), inner.clone())
                .prop_map(|(o, a)| format!("{o}{a}")),
            inner.clone().prop_map(|a| format!("({a})")),
            (inner.clone(), inner.clone(), inner.clone())
                .prop_map(|(a, b, c)| format!("<{a}, {b}, {c}>")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("<{a} {b}>")),
            (inner.clone(), field).prop_map(|(a, f)| format!("({a}).{f}")),
            (
                prop::sample::select(vec!["sin", "sqrt", "int", "abs"]),
                inner.clone()
            )
                .prop_map(|(f, a)| format!("{f}({a})")),
            (inner.clone(), inner.clone(), inner.clone())
                .prop_map(|(c, a, b)| format!("({c} ? {a} : {b})")),
            (inner.clone(), inner.clone(), inner).prop_map(|(c, a, b)| format!("{c} ? {a} : {b}")),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 600, ..ProptestConfig::default() })]

    /// Any expression of the compiled subset and beyond, well formed or not: the same
    /// outcome both ways, on both passes, whether or not a name changes kind.
    #[test]
    fn random_expressions_read_the_same_both_ways(expr in expression(), retype in any::<bool>()) {
        same_both_ways(&expr, retype);
    }
}
