sphere { 0, 1 pigment { slope { 0 } } }
// error: 1:33 the slope direction must be a non-zero vector
