// cubic is poly of order 3; polynomial's terms land where poly's list has them
// (x^2 is the first of order 2's ten, y^2 the fifth, the constant the last).
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1> sturm }
polynomial { 2, xyz(2, 0, 0): 1, xyz(0, 2, 0): 2 xyz(0, 0, 0): -1 }
poly { 7, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
  0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
  0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
  0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2> }
// model: objects[0].shape.Poly.order = 3
// model: objects[0].shape.Poly.coefficients.len = 20
// model: objects[1].shape.Poly.coefficients = [1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0, -1.0]
// model: objects[2].shape.Poly.order = 7
// model: objects[2].shape.Poly.coefficients.len = 120
