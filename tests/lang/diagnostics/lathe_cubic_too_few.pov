lathe { cubic_spline 3, <0,0>, <1,1>, <0.5,2> }
// error: 1:22 a cubic_spline lathe needs at least four points, found 3
