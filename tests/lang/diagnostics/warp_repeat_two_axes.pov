// image: 16x16
sphere { 0, 1 pigment { bozo warp { repeat <1, 1, 0> } } }
// error: 2:37 a repeat warp repeats along exactly one axis
