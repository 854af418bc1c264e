// image: 16x16
sphere { 0, 1 pigment { bozo warp { repeat x } } }
// error: 2:37 unsupported: `warp { repeat }` is not supported yet
