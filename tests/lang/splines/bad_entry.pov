#declare S = spline { 0, <1,2,3> 1, "x" }
// error: 1:37 a spline entry is a vector, found a string
