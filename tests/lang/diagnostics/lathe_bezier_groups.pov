lathe { bezier_spline
  5, <0,0>, <1,0>, <1,1>, <0,1>, <0,2> }
// error: 2:3 a bezier_spline lathe needs groups of four points, found 5
