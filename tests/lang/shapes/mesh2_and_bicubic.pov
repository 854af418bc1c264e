mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <0, 1>, <1, 1> }
  texture_list { 2, texture { pigment { rgb x } } texture { pigment { rgb y } } }
  face_indices { 3, <0, 1, 2>, 1, <1, 3, 2>, 0, 1, 0, <0, 0, 1> }
  inside_vector z
}
bicubic_patch { type 0 flatness 0.01 u_steps 3 v_steps 1 uv_vectors <0, 0>, <2, 0>, <2, 2>, <0, 2>
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>, <0, 0, 1>, <1, 1, 1>, <2, 1, 1>, <3, 0, 1>,
  <0, 0, 2>, <1, 1, 2>, <2, 1, 2>, <3, 0, 2>, <0, 0, 3>, <1, 0, 3>, <2, 0, 3>, <3, 0, 3>
  translate x
}
// The third face is degenerate and dropped; uvs pair with the vertices.
// model: objects[0].shape.Mesh.0.faces.len = 2
// model: objects[0].shape.Mesh.0.faces[0] = { vertices: [0, 1, 2], uvs: Some([0, 1, 2]), textures: Some([1, 1, 1]) }
// model: objects[0].shape.Mesh.0.faces[1].textures = Some([0, 1, 0])
// model: objects[0].shape.Mesh.0.textures.len = 2
// model: objects[0].shape.Mesh.0.inside_vector = Some(<0, 0, 1>)
// model: objects[1].shape.BicubicPatch.0 = { kind: 0, flatness: 0.01, u_steps: 3, v_steps: 1 }
// model: objects[1].shape.BicubicPatch.0.points[5] = <1, 1, 1>
// model: objects[1].shape.BicubicPatch.0.uv[2] = <2, 2>
