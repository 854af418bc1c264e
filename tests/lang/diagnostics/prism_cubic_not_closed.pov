prism { cubic_spline 0, 1,
  6, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0> }
// error: 2:3 a cubic spline prism needs a control point after point 6, which closes its sub-shape
