#version 3.7;
plane { z, 0 pigment { magnet 3 mandel 30 } }
// error: 2:31 the magnet type must be 1 or 2
