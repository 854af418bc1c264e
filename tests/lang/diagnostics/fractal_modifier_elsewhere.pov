#version 3.7;
plane { z, 0 pigment { bozo exterior 2, 1 } }
// error: 2:38 `exterior` works only with mandel, julia and magnet
