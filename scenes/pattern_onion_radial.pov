// onion and radial with colour maps and frequency
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { onion color_map { [0 rgb 0.1] [0.05 rgb 0.1] [0.9 rgb <0.9,0.8,0.6>] [1 rgb 1] } scale 0.5 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1 pigment { radial frequency 8 color_map { [0 rgb <0.1,0.1,0.5>] [0.5 rgb <1,1,1>] [1 rgb <0.1,0.1,0.5>] } rotate x*90 } finish { ambient 0.15 diffuse 0.7 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> rotate y*25 translate <1.5, 0, 0.3> pigment { onion scallop_wave frequency 2 color_map { [0 rgb <0.6,0,0>] [1 rgb <1,0.9,0.7>] } scale 0.6 translate <0.3,0.2,0.1> } }
