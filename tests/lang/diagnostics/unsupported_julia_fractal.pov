julia_fractal { <-0.08, 0, -0.83, -0.03> }
fog { distance 3 color rgb 1 }
#declare T = text { ttf "a.ttf" "x" 1, 0 }
object { T translate x }
union { sphere { 0, 1 } lathe { linear_spline 2, <0,0>, <1,1> } }
sphere { 0, 1 photons { target } }
// error: 1:1 unsupported: `julia_fractal` is not supported yet
