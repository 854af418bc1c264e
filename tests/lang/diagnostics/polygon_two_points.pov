polygon {
  2, <0,0>, <1,0>
}
// error: 2:3 a polygon needs at least three points, found 2
