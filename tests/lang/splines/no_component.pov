#declare F = function { spline { 0, <1,2,3> 1, <2,3,4> } }
#declare G = function { F(x) + 1 }
// error: 2:30 expected `.` after `F(...)`: a spline function gives a vector; read a component like `.y`, found `+`
