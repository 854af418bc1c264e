// image_map from a PNG: planar (repeated, nearest pixel), spherical with interpolate 2, cylindrical,
// and interpolate 4 (neighbours by inverse squared distance) on a tile seen up close
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { image_map { png "images/test_card.png" } rotate x*90 scale 2 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1 pigment { image_map { png "images/test_card.png" map_type 1 interpolate 2 } rotate y*40 } finish { ambient 0.15 diffuse 0.7 } translate <0, 0, 0> }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> pigment { image_map { png "images/test_card.png" map_type 2 interpolate 2 } scale <1, 1.6, 1> } rotate y*25 translate <1.5, 0, 0.3> }
box { <-0.6, 0, -2.2>, <0.6, 0.05, -1.4> pigment { image_map { png "images/test_card.png" interpolate 4 } rotate x*90 scale <1.2, 1, 0.8> translate <-0.6, 0, -2.2> } finish { ambient 0.3 diffuse 0.6 } }
