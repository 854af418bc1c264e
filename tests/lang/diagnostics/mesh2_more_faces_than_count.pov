mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
  face_indices { 1, <0, 1, 2>, <1, 3, 2> }
}
// error: 3:32 face_indices has more entries than its count (1)
