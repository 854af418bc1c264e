#version 3.7;
plane { z, 0 pigment { julia <0.3, 0.2>, -5 } }
// error: 2:42 max_iteration must be 0 or more (and below 2^32)
