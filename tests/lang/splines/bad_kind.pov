#declare S = spline { 0, <1,2,3> 1, <2,3,4> }
#declare V = S(0.5, bezier_spline);
// error: 2:21 expected a spline kind (`linear_spline`, `quadratic_spline`, `cubic_spline`, `natural_spline`), found `bezier_spline`
