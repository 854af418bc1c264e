// image_pattern: an image's grey values (raw, without gamma) as a pattern in colour maps
// (planar, spherical with interpolate 2, cylindrical) and a texture_map
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> look_at <0, 0.6, 0> right x*image_width/image_height angle 50 }
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0
  pigment { image_pattern { png "images/test_card.png" } color_map { [0 rgb <0.1,0.1,0.4>] [0.5 rgb <0.9,0.6,0.2>] [1 rgb 1] } rotate x*90 scale 2 }
  finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1
  texture { image_pattern { png "images/test_card.png" map_type 1 interpolate 2 }
    texture_map { [0 pigment { rgb <0.8,0.1,0.1> } finish { phong 0.8 }] [1 pigment { rgb <0.9,0.9,0.7> } finish { phong 0.8 }] }
    rotate y*40 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8>
  pigment { image_pattern { png "images/test_card.png" map_type 2 interpolate 2 } color_map { [0 rgb 0.1] [1 rgb <0.3,0.9,0.5>] } scale <1, 1.6, 1> }
  finish { phong 0.5 }
  rotate y*25 translate <1.5, 0, 0.3> }
