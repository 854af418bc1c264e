ovus { 1, 0.5 }
fog { distance 3 color rgb 1 }
#declare T = text { ttf "a.ttf" "x" 1, 0 }
object { T translate x }
union { sphere { 0, 1 } lathe { linear_spline 2, <0,0>, <1,1> } }
sphere { 0, 1 photons { target } }
// error: 1:1 unsupported: `ovus` is not supported yet
