#version 3.7;
sphere { 0, 1 pigment { bozo scale 2 warp { turbulence 0.5 octaves 3 }
  rotate y*10 frequency 3 phase 0.1 sine_wave color_map { [0 rgb 0] [1 rgb 1] } } }
// model: objects[0].texture.pigment.kind.ColourMap.map.len = 2
// model: objects[0].texture.pigment.kind.ColourMap.pattern = { frequency: 3, phase: 0.1, wave: Sine }
// The scale before the warp moved into the chain; the rotate after it stays outside.
// model: objects[0].texture.pigment.kind.ColourMap.pattern.warps.len = 2
// model: objects[0].texture.pigment.kind.ColourMap.pattern.warps[0].Transform.len = 1
// model: objects[0].texture.pigment.kind.ColourMap.pattern.warps[1].Turbulence.0 = { amount: <0.5, 0.5, 0.5>, octaves: 3 }
// model: objects[0].texture.pigment.transform maps <1, 0, 0> to <0.984807753012208, 0, -0.17364817766693033>
