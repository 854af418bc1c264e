// A circular, oriented, jittered area light (5x5) behind and above the objects.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source {
  <2, 5, 3> color rgb 1
  area_light <2, 0, 0>, <0, 2, 0>, 5, 5
  circular orient jitter
}

plane { y, 0 pigment { color rgb <0.85, 0.85, 0.8> } }
sphere { <-0.5, 1, -0.5>, 1 pigment { color rgb <0.8, 0.4, 0.3> } finish { specular 0.4 } }
box { <0.8, 0, -1.5>, <1.6, 1.6, -0.7> pigment { color rgb <0.4, 0.6, 0.3> } }
