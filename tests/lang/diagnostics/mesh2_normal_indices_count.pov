mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
  normal_vectors { 1, <0, 0, 1> }
  face_indices { 2, <0, 1, 2>, <1, 3, 2> }
  normal_indices { 1, <0, 0, 0> }
}
// error: 5:3 normal_indices lists 1 faces, but face_indices has 2
