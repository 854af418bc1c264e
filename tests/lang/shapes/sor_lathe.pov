sor { 4, <0,0>, <1,1>, <0.5,2>, <1,3> open sturm }
lathe { bezier_spline 4, <0,0>, <1,0>, <1,1>, <0,1> }
lathe { 2, <1,0>, <1,1> }
// model: objects[0].shape.Sor.0 = { open: true }
// model: objects[0].shape.Sor.0.points[2] = <0.5, 2>
// model: objects[1].shape.Lathe.0 = { spline: Bezier }
// model: objects[1].shape.Lathe.0.points.len = 4
// model: objects[2].shape.Lathe.0 = { spline: Linear }
