// An area light with sizes that are not 2^k+1 (6 by 2): POV-Ray's irregular grid weights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 4, -6>
  look_at <0, 0.5, 0>
  right x*image_width/image_height
  angle 45
}
light_source {
  <-2, 5, -2> color rgb 1
  area_light <4, 0, 0>, <0, 0, 1>, 6, 2
}

plane { y, 0 pigment { color rgb 0.85 } }
box { <-0.3, 0, -0.3>, <0.3, 1.5, 0.3> pigment { color rgb <0.9, 0.3, 0.3> } }
sphere { <1.5, 0.5, 0.5>, 0.5 pigment { color rgb <0.3, 0.8, 0.4> } }
