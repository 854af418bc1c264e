// spiral1 with 5 and 3 arms, and leopard
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { spiral1 5 color_map { [0 rgb 0.05] [0.1 rgb 0.05] [0.9 rgb <0.9,0.9,0.8>] [1 rgb <0.9,0.9,0.8>] } scale 0.5 rotate x*90 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1 pigment { spiral1 3 color_map { [0 rgb <0.1,0.2,0.6>] [1 rgb <1,0.8,0.3>] } scale 0.4 rotate <30,20,0> } finish { ambient 0.15 diffuse 0.7 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> rotate y*25 translate <1.5, 0, 0.3> pigment { leopard color_map { [0 rgb 0.05] [1 rgb <1,0.7,0.2>] } scale 0.1 } }
