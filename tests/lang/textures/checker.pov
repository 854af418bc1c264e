plane { y, -1 pigment { checker } }
plane { <0,2,0>, 1 pigment { checker color rgb 1, pigment { rgb 0.5 } scale 2 } }
// model: objects[0].texture.pigment.kind.List.entries[0].kind = Solid({ rgb: <0, 0, 1>, filter: 0, transmit: 0 })
// model: objects[0].texture.pigment.kind.List.entries[1].kind = Solid({ rgb: <0, 1, 0>, filter: 0, transmit: 0 })
// model: objects[1].texture.pigment.kind.List.entries[1].kind = Solid({ rgb: <0.5, 0.5, 0.5>, filter: 0, transmit: 0 })
// model: objects[1].texture.pigment.transform maps <1, 0, 0> to <2, 0, 0>
// model: objects[1].shape = Plane { normal: <0, 1, 0>, distance: 1 }
