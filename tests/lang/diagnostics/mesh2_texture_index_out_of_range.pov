mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  texture_list { 1, texture { pigment { rgb 1 } } }
  face_indices { 1, <0, 1, 2>, 1 }
}
// error: 4:32 index 1 is out of range: texture_list has 1 entries (0 to 0)
