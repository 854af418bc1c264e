// image: 16x16
sphere { 0, 1 texture { texture_map { [0 pigment { rgb 1 }] } } }
// error: 2:25 `texture_map` needs a pattern before it
