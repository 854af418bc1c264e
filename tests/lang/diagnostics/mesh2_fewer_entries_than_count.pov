mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  face_indices { 1, <0, 1, 2> }
}
// error: 2:55 vertex_vectors ends after 3 entries, but its count says 4
