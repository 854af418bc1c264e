#declare P = function { pigment { rgb 1 } }
#declare F = function { P(x, y, z) + 1 }
// error: 2:36 expected `.` after `P(...)`: a pigment function gives a colour; read a channel like `.red`, found `+`
