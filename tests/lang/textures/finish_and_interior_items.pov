#version 3.7;
sphere { 0, 1 finish { diffuse 0.6, 0.2 crand 0.1 fresnel conserve_energy }
  interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color rgb <1,0.5,0> } }
// model: objects[0].texture.finish = { diffuse: 0.6, diffuse_back: 0.2, crand: 0.1, fresnel: true, conserve_energy: true }
// model: objects[0].interior = Some({ ior: 1.5, fade_distance: 2, fade_power: 1001, fade_colour: <1, 0.5, 0> })
