mesh2 {
  vertex_vectors { 3 <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  face_indices { 1 <0, 1, 2> }
}
bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 4,
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>, <0, 0, 1>, <1, 1, 1>, <2, 1, 1>, <3, 0, 1>,
  <0, 0, 2>, <1, 1, 2>, <2, 1, 2>, <3, 0, 2>, <0, 0, 3>, <1, 0, 3>, <2, 0, 3>, <3, 0, 3>
}
// A count may be followed by its first vector without a comma (objects/mesh2.pov), and a
// comma may end a patch's options (objects/primitiv.pov): a `<` there is no comparison.
// model: objects[0].shape.Mesh.0.vertices.len = 3
// model: objects[0].shape.Mesh.0.faces.len = 1
// model: objects[1].shape.BicubicPatch.0.v_steps = 4
