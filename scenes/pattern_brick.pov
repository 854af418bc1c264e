// brick: default and custom brick_size and mortar
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { brick rgb 0.85, rgb <0.55,0.15,0.05> scale 0.1 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1 pigment { brick rgb 1, rgb <0.6,0.3,0.1> brick_size <1,0.5,0.7> mortar 0.08 scale 0.5 } finish { ambient 0.15 diffuse 0.7 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> rotate y*25 translate <1.5, 0, 0.3> pigment { brick rgb 0.2, rgb <0.8,0.7,0.5> brick_size 0.5 mortar 0.05 rotate y*20 } }
