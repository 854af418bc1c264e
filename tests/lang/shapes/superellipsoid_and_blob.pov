superellipsoid { <0.25, 1> }
blob {
  threshold 0.6
  sphere { <1, 0, 0>, 2, strength 1.5 }
  cylinder { 0, y, 0.5, -1 scale 2 }
  component 1, 0.8, <0, 0, 1>
  sturm hierarchy off
  translate x
}
// model: objects[0].shape = Superellipsoid { east_west: 0.25, north_south: 1 }
// model: objects[1].shape.Blob.0.threshold = 0.6
// model: objects[1].shape.Blob.0.components.len = 3
// model: objects[1].shape.Blob.0.components[0] = { kind: Sphere { center: <1, 0, 0> }, radius: 2, strength: 1.5 }
// model: objects[1].shape.Blob.0.components[1] = { kind: Cylinder { end1: <0, 0, 0>, end2: <0, 1, 0> }, radius: 0.5, strength: -1 }
// model: objects[1].shape.Blob.0.components[1].transform maps <0, 1, 0> to <0, 2, 0>
// model: objects[1].shape.Blob.0.components[2].kind = Sphere { center: <0, 0, 1> }
// model: objects[1].transform maps <0, 0, 0> to <1, 0, 0>
