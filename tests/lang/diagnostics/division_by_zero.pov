sphere { 0, 1 / 0 }
// error: 1:15 division by zero
