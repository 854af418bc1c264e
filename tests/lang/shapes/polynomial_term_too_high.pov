polynomial { 2, xyz(2, 1, 0): 1 }
// error: 1:17 the term xyz(2, 1, 0) is of a higher order than the polynomial's 2
