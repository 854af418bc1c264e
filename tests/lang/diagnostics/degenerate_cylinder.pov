sphere { 0, 1 }
  cylinder { y, y, 1 }
// error: 2:3 degenerate cylinder: the base point equals the cap point
