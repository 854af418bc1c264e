mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  face_indices { 1, <0, 1, 3> }
}
// error: 3:21 index 3 is out of range: vertex_vectors has 3 entries (0 to 2)
