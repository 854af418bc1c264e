// Finish conserve_energy: with it, what a filtering or transmitting surface lets through is
// reduced by what it reflects (per channel for a coloured reflection); the first sphere,
// without it, shows the difference. No ior: refraction is not what this scene checks.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 3 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 6, -5> color rgb 1 }
background { color rgb <0.2, 0.3, 0.6> }

plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.2, 0.3, 0.2> scale 1.5 } }
plane { z, 5 pigment { color rgb <0.9, 0.4, 0.2> } }
box { <-4, 0, -9>, <4, 3, -8.5> pigment { color rgb <0.3, 0.7, 0.4> } }
sphere { <-2.1, 0.7, 0>, 0.6 pigment { color rgbt <0.8, 0.8, 0.8, 0.7> } finish { diffuse 0.2 reflection 0.5 } }
sphere { <-0.7, 0.7, 0>, 0.6 pigment { color rgbt <0.8, 0.8, 0.8, 0.7> } finish { diffuse 0.2 reflection 0.5 conserve_energy } }
sphere { <0.7, 0.7, 0>, 0.6 pigment { color rgbf <0.9, 0.6, 0.3, 0.8> } finish { diffuse 0.2 reflection { 0.1, 0.8 falloff 2 } conserve_energy } }
sphere { <2.1, 0.7, 0>, 0.6 pigment { color rgbt <0.7, 0.8, 0.9, 0.6> } finish { diffuse 0.2 reflection rgb <0.6, 0.3, 0.1> conserve_energy } }
