#version 3.7;
plane { z, 0 pigment { quilted control0 0 control1 0.5 } }
plane { z, 0 normal { magnet 2 julia <0.4, 0.3> 20, 0.7 exterior 3, 0.5 interior 6, 2 } }
plane { z, 0 texture { julia <-0.5, 0.5> 10 exponent 4 texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }
plane { z, 0 pigment { cells } }
plane { z, 0 pigment { mandel 80 } }
plane { z, 0 pigment { mandel 80 exponent 3 } }
// model: objects[0].texture.pigment.kind.ColourMap.pattern.kind.Quilted.0 = { control0: 0, control1: 0.5 }
// model: objects[1].texture.normal.amount = 0.7
// model: objects[1].texture.normal.pattern.kind.Fractal.0 = { formula: Magnet2, julia: Some([0.4, 0.3]), max_iteration: 20, exterior: (Imaginary, 0.5), interior: (Absolute, 2) }
// model: objects[2].texture.map.pattern.kind.Fractal.0 = { formula: Power(4), julia: Some([-0.5, 0.5]), max_iteration: 10 }
// model: objects[3].texture.pigment.kind.ColourMap.pattern.kind = Cells
// model: objects[4].texture.pigment.kind.ColourMap.map.len = 5
// model: objects[5].texture.pigment.kind.ColourMap.map.len = 2
