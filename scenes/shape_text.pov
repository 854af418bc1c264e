// Text: glyph outlines (lines and quadratic curves) extruded along z, in four fonts, with kerning (AV, To), a vector offset between letters, under rotate and scale, and carved out of a box by a difference.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.4, -10> look_at <0, 1.2, 0> right x*image_width/image_height angle 52 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
text {
  ttf "timrom.ttf" "AVTo" 0.4, 0
  scale 1.4 rotate <0, -15, 0> translate <-4.3, 1.7, 0.6>
  pigment { color rgb <0.9, 0.2, 0.2> } finish { F }
}
difference {
  box { <-1.7, 0, -0.3>, <1.7, 1.3, 0.3> }
  text { ttf "cyrvetic.ttf" "CSG" 0.5, 0 scale <1.3, 1.1, 1> translate <-1.25, 0.25, -0.4> }
  rotate <0, 10, 0> translate <0.6, 0, -1.4>
  pigment { color rgb <0.9, 0.8, 0.2> } finish { F }
}
text {
  ttf "crystal.ttf" "3.7" 0.3, <0.05, 0.15, 0>
  scale <1.6, 2, 1> rotate <0, 25, 8> translate <0.9, 1.5, 1.4>
  pigment { color rgb <0.2, 0.3, 0.9> } finish { F }
}
text {
  ttf "povlogo.ttf" "P" 0.25, 0
  scale 1.6 rotate <0, -30, 0> translate <-3.9, 0, -2.4>
  pigment { color rgb <0.2, 0.7, 0.3> } finish { F }
}
intersection {
  text { ttf "timrom.ttf" "ab" 1, 0 scale 1.3 translate <-0.6, 0, -0.5> }
  sphere { 0, 0.75 translate <0, 0.45, 0> }
  rotate <0, -20, 0> translate <3.1, 0.05, -2.6>
  pigment { color rgb <0.8, 0.4, 0.9> } finish { F }
}
