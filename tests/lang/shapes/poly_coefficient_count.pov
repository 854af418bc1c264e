poly { 2, <1, 2, 3> }
// error: 1:11 a poly of order 2 takes 10 coefficients, found 3
