// gradient patterns: a colour map with steps and blends, frequency, phase and wave types
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { gradient x color_map { [0 rgb <0.1,0.1,0.3>] [0.3 rgb <0.9,0.9,0.2>] [0.3 rgb <0.8,0.2,0.1>] [1 rgb 1] } scale 0.8 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1 pigment { gradient y frequency 3 phase 0.2 sine_wave color_map { [0 rgb <0,0.3,0.8>] [1 rgb 1] } } finish { ambient 0.15 diffuse 0.7 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> rotate y*25 translate <1.5, 0, 0.3> pigment { gradient <1,1,0> triangle_wave frequency 2 color_map { [0 rgb 0.1] [0.5 rgb <0.9,0.4,0.1>] [1 rgb <1,1,0.6>] } scale 0.7 } }
