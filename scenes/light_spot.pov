// Spotlights (radius, falloff, tightness) and a point light whose light fades with distance.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 5, -7>
  look_at <0, 0.5, 0>
  right x*image_width/image_height
  angle 50
}
light_source {
  <-2, 5, -1> color rgb <1, 0.9, 0.7>
  spotlight point_at <-1.5, 0, 0.5> radius 12 falloff 25
}
light_source {
  <2.5, 4, -2> color rgb <0.6, 0.8, 1>
  spotlight point_at <1.5, 0, 0.5> radius 20 falloff 30 tightness 20
}
light_source { <0, 2, 3> color rgb 1.5 fade_distance 2 fade_power 2 }

plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.05 } }
sphere { <-1.5, 0.6, 0.5>, 0.6 pigment { color rgb <0.9, 0.9, 0.9> } finish { phong 0.4 } }
box { <1, 0, 0>, <2, 1, 1> pigment { color rgb <0.9, 0.6, 0.3> } }
