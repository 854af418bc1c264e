//! `julia_fractal`'s parameters, in the scene's own terms.

/// How 4-D points multiply: quaternions (i^2 = j^2 = k^2 = ijk = -1) or the commutative
/// hypercomplex numbers (ij = k, k^2 = 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JuliaAlgebra {
    Quaternion,
    Hypercomplex,
}

/// The iterated function: z -> f(z) + c.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum JuliaFunction {
    Sqr,
    Cube,
    Exp,
    Reciprocal,
    Sin,
    Cos,
    Sinh,
    Cosh,
    Ln,
    /// `pwr(x, y)`: z to the complex power x + i y.
    Pwr(f64, f64),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JuliaFractal {
    /// The Julia parameter c.
    pub c: [f64; 4],
    pub algebra: JuliaAlgebra,
    pub function: JuliaFunction,
    pub max_iteration: u32,
    /// The marching step is 1 / precision.
    pub precision: f64,
    /// The 3-D space is the hyperplane `slice . p = distance` of the 4-D one.
    pub slice: [f64; 4],
    pub distance: f64,
}

impl Default for JuliaFractal {
    /// POV-Ray's defaults: quaternion sqr, 20 iterations, precision 20, the slice w = 0.
    fn default() -> JuliaFractal {
        JuliaFractal {
            c: [0.0; 4],
            algebra: JuliaAlgebra::Quaternion,
            function: JuliaFunction::Sqr,
            max_iteration: 20,
            precision: 20.0,
            slice: [0.0, 0.0, 0.0, 1.0],
            distance: 0.0,
        }
    }
}
