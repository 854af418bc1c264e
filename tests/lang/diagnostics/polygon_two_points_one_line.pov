polygon { 2, 0, x }
// error: 1:11 a polygon needs at least three points, found 2
