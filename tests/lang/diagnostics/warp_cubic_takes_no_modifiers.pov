sphere { 0, 1 pigment { bozo warp { cubic dist_exp 2 } } }
// error: 1:43 expected `}` to close the warp, found `dist_exp`
