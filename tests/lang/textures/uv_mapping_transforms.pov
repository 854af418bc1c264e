// Measured with povray on a sphere: u doubles for the first two, is unchanged for the others.
sphere { 0, 1 texture { uv_mapping pigment { gradient x } scale 0.5 } }
sphere { 0, 1 pigment { uv_mapping gradient x scale 0.5 } }
sphere { 0, 1 texture { pigment { uv_mapping gradient x } scale 0.5 } }
sphere { 0, 1 pigment { uv_mapping gradient x } scale 0.5 rotate y*30 }
// model: objects[0].texture.pigment.uv_mapping = true
// model: objects[1].texture.pigment.uv_mapping = true
// model: objects[2].texture.pigment.uv_mapping = true
// model: objects[3].texture.pigment.uv_mapping = true
// model: objects[0].texture.pigment.transform unmaps <0.25, 0, 0> to <0.5, 0, 0> within 1e-12
// model: objects[1].texture.pigment.transform unmaps <0.25, 0, 0> to <0.5, 0, 0> within 1e-12
// model: objects[2].texture.pigment.transform unmaps <0.25, 0, 0> to <0.25, 0, 0> within 1e-12
// model: objects[3].texture.pigment.transform unmaps <0.25, 0, 0> to <0.25, 0, 0> within 1e-12
