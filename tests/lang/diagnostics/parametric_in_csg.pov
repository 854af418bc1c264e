difference {
  sphere { 0, 1 }
  parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> }
}
// error: 3:3 unsupported: `parametric` is not supported yet
