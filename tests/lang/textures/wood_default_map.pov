// A wood pigment without a colour map shows POV-Ray's own: light brown below 0.6, dark
// brown above (measured: the default renders exactly as this map written out).
plane { y, 0 pigment { wood } }
plane { y, 1 pigment { gradient x } }
// model: objects[0].texture.Some.0.pigment.kind.ColourMap.map.len = 4
// model: objects[0].texture.Some.0.pigment.kind.ColourMap.map[1] = (0.6, { rgb: <0.666, 0.312, 0.2>, filter: 0, transmit: 0 })
// model: objects[0].texture.Some.0.pigment.kind.ColourMap.map[2] = (0.6, { rgb: <0.4, 0.1333, 0.066>, filter: 0, transmit: 0 })
// model: objects[1].texture.Some.0.pigment.kind.ColourMap.map.len = 2
