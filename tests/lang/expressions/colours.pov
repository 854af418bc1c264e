#declare White = rgb 1;
#declare Clear = rgbf 1;
background { White * 0.3 }
plane { y, 0 pigment { color red 1 green 0.5 blue 0.2 filter 0.1 transmit 0.3 } }
plane { y, 0 pigment { rgbft <1,2,3,4,5> } }
plane { y, 0 pigment { Clear } }
plane { y, 0 pigment { color rgb 1 * 0.5 } }
plane { y, 0 pigment { color <1,0,0,0.5> } }
plane { y, 0 pigment { rgbt <1,1,1,0.25> } }
// model: background.rgb = <0.3, 0.3, 0.3>
// model: objects[0].texture.pigment.kind = Solid({ rgb: <1, 0.5, 0.2>, filter: 0.1, transmit: 0.3 })
// model: objects[1].texture.pigment.kind = Solid({ rgb: <1, 2, 3>, filter: 4, transmit: 5 })
// model: objects[2].texture.pigment.kind = Solid({ rgb: <1, 1, 1>, filter: 1, transmit: 0 })
// model: objects[3].texture.pigment.kind = Solid({ rgb: <0.5, 0.5, 0.5>, filter: 0, transmit: 0 })
// model: objects[4].texture.pigment.kind.Solid.0.filter = 0.5
// model: objects[5].texture.pigment.kind.Solid.0.transmit = 0.25
// model: objects[5].texture.pigment.kind.Solid.0.filter = 0
// value: White = rgbft <1, 1, 1, 0, 0>
