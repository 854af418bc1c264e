// image: 16x16
sphere { 0, 1 pigment { gradient x color_map { [0 rgb 0] [1 } } }
// error: 2:61 expected an expression, found `}`
