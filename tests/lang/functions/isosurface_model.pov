difference {
  sphere { 0, 1 }
  isosurface { function { x + y } contained_by { sphere { <0, 1, 0>, 2 } } threshold 0.5 open max_gradient 3 }
}
// model: objects[0].shape.Difference.0[1].shape.Isosurface.0 = { threshold: 0.5, max_gradient: 3, open: true, accuracy: 0.001 }
// model: objects[0].shape.Difference.0[1].shape.Isosurface.0.container = Sphere { center: <0, 1, 0>, radius: 2 }
