// A parallel light, a cylinder light (radius, falloff, tightness) and a shadowless fill.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 5, -7>
  look_at <0, 0.5, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-10, 8, -4> color rgb 0.6 parallel point_at <0, 0, 0> }
light_source {
  <1, 6, 0> color rgb <1, 0.8, 0.5>
  cylinder point_at <1, 0, 0.5> radius 0.8 falloff 1.6 tightness 2
}
light_source { <0, 3, -6> color rgb 0.15 shadowless }

plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.05 } }
sphere { <-1.2, 0.7, 0.5>, 0.7 pigment { color rgb <0.3, 0.7, 0.9> } finish { phong 0.6 } }
box { <0.5, 0, 0>, <1.3, 1.4, 0.8> pigment { color rgb <0.9, 0.9, 0.9> } }
