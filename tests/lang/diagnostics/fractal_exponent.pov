#version 3.7;
plane { z, 0 pigment { mandel 30 exponent 34 } }
// error: 2:43 the fractal exponent must be from 2 to 33
