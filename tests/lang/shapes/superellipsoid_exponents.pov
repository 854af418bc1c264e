superellipsoid { <0, 1> }
// error: 1:18 the superellipsoid's exponents <0, 1> must be positive
