// Adaptive area lights: a 9x9 grid with `adaptive 1` and jitter, whose data-dependent
// subdivision penumbra reproduces per shaded point.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3.5, -6>
  look_at <0, 0.5, 0>
  right x*image_width/image_height
  angle 45
}
light_source {
  <-2, 5, -2> color rgb 1
  area_light <3, 0, 0>, <0, 0, 3>, 9, 9
  adaptive 1
  jitter
}

plane { y, 0 pigment { color rgb 0.85 } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.9, 0.5, 0.3> } finish { phong 0.5 } }
box { <1.2, 0, -1>, <1.6, 1.8, -0.6> pigment { color rgb <0.3, 0.6, 0.9> } }
