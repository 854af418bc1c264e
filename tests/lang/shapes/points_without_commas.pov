// As in povray's interior/atten2.pov and objects/sor1.pov: no comma after the count or
// between the points.
prism { -0.5, 0.5, 4
  <-1, -0.3>, <1, 0>, <-1, 0.3>, <-1, -0.3> }
sor { 5, <0, 0> <1, 0> <0.5, 1> <0.6, 2> <0.7, 2> }
// model: objects[0].shape.Prism.0.points.len = 4
// model: objects[0].shape.Prism.0.points[0] = <-1, -0.3>
// model: objects[1].shape.Sor.0.points.len = 5
