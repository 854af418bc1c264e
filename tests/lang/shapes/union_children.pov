#declare U = union { sphere { 0, 1 } sphere { x, 1 pigment { rgb 1 } } pigment { rgb <1,0,0> } }
object { U translate y no_shadow }
// model: objects[0].flags.no_shadow = true
// model: objects[0].shape.Union.0[0].texture = None
// model: objects[0].shape.Union.0[1].texture.pigment.kind = Solid({ rgb: <1, 1, 1>, filter: 0, transmit: 0 })
// model: objects[0].shape.Union.0[0].transform maps <0, 0, 0> to <0, 1, 0>
// model: objects[0].transform maps <0, 0, 0> to <0, 1, 0>
// model: objects[0].texture.pigment.transform maps <0, 0, 0> to <0, 1, 0>
