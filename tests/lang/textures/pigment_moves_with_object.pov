sphere { <1,2,3>, 0.5 pigment { color rgb <1,0,0> } translate x*2 }
// model: objects[0].shape = Sphere { center: <1, 2, 3>, radius: 0.5 }
// model: objects[0].transform maps <0, 0, 0> to <2, 0, 0>
// model: objects[0].texture.pigment.kind = Solid({ rgb: <1, 0, 0>, filter: 0, transmit: 0 })
// The pigment was attached before the translate, so it moves with the object.
// model: objects[0].texture.pigment.transform maps <0, 0, 0> to <2, 0, 0>
