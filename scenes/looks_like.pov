// A light with a visible bulb (looks_like): the bulb shows but does not shadow its light.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.5, -6>
  look_at <0, 1, 0>
  right x*image_width/image_height
  angle 45
}
light_source {
  <0.5, 2.2, 0> color rgb <1, 0.95, 0.8>
  looks_like { sphere { <0, 0, 0>, 0.25 pigment { color rgb <1, 1, 0.8> } finish { ambient 1 diffuse 0 } } }
}
light_source { <-4, 6, -6> color rgb 0.3 }

plane { y, 0 pigment { color rgb 0.8 } }
sphere { <-1, 0.7, 0.5>, 0.7 pigment { color rgb <0.4, 0.7, 0.4> } }
box { <0.8, 0, -0.5>, <1.8, 0.8, 0.5> pigment { color rgb <0.7, 0.5, 0.9> } }
