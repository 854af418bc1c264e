#version 3.7;
plane { z, 0 pigment { magnet 1 julia <0.3, 0.2>, 30 exponent 3 } }
// error: 2:63 `exponent` works only with mandel and julia, not magnet
