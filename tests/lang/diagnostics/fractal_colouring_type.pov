#version 3.7;
plane { z, 0 normal { mandel 30, 0.5 interior 7, 1 } }
// error: 2:47 the interior type must be 0 to 6
