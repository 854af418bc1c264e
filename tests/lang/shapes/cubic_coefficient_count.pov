cubic { <1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21> }
// error: 1:9 a cubic of order 3 takes 20 coefficients, found 21
