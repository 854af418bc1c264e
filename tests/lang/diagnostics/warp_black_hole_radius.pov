sphere { 0, 1 pigment { bozo warp { black_hole <0, 0, 0>, 0 } } }
// error: 1:59 a black hole's radius must be positive
