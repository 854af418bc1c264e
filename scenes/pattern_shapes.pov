// spherical, cylindrical, boxed and wood in a pigment map; cubic and poly waves
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { gradient x pigment_map { [0 checker rgb 0.2, rgb 0.8] [0.5 boxed color_map { [0 rgb <0.7,0.1,0.1>] [1 rgb <1,1,0.5>] } scale 0.5] [1 wood color_map { [0 rgb <0.5,0.3,0.1>] [1 rgb <0.9,0.7,0.4>] } scale 0.3] } scale 6 translate -3*x } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1 pigment { spherical cubic_wave color_map { [0 rgb <0.1,0.6,0.1>] [1 rgb <1,1,0.3>] } scale 1.1 translate <-1.3,1,-0.5> } finish { ambient 0.15 diffuse 0.7 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> rotate y*25 translate <1.5, 0, 0.3> pigment { cylindrical poly_wave 2 color_map { [0 rgb <0.2,0.2,0.9>] [0.5 rgb <1,0.2,0.2>] [1 rgb 0.9] } scale 0.9 } }
