poly { 8, <1, 2> }
// error: 1:8 a polynomial's order must be a whole number from 2 to 7, found 8
