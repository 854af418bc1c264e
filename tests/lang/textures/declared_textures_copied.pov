#declare T = texture { pigment { rgb 1 } finish { phong 1 } }
sphere { 0, 1 texture { T finish { phong 0.5 } } }
sphere { 0, 1 texture { T } }
#declare P = pigment { rgb <0,1,0> }
box { -1, 1 pigment { P scale 3 } }
// model: objects[0].texture.finish.phong = 0.5
// model: objects[1].texture.finish.phong = 1
// model: objects[2].texture.pigment.kind = Solid({ rgb: <0, 1, 0>, filter: 0, transmit: 0 })
// model: objects[2].texture.pigment.transform maps <1, 0, 0> to <3, 0, 0>
