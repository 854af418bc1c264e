prism { conic_sweep cubic_spline 0.2, 1, 7, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1> open sturm }
prism { 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,1> }
// model: objects[0].shape.Prism.0 = { spline: Cubic, conic: true, height1: 0.2, height2: 1, open: true }
// model: objects[0].shape.Prism.0.points.len = 7
// model: objects[0].shape.Prism.0.points[1] = <1, 0>
// model: objects[1].shape.Prism.0 = { spline: Linear, conic: false }
// warning: 2:1 the linear prism is not closed; closing it
