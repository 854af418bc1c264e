mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  normal_vectors { 2, <0, 0, 1>, <0, 0, 1> }
  face_indices { 1, <0, 1, 2> }
}
// error: 1:1 without normal_indices the 2 normal_vectors pair with the 3 vertex_vectors, so their counts must agree
