// Object modifiers: clipped_by, bounded_by, hollow, no_shadow, no_image, no_reflection, double_illuminate, and inverse on a whole CSG.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
// A mirror at the back shows what no_reflection and no_image do.
box { <-5, 0, 3>, <5, 4, 3.2> pigment { color rgb 0.1 } finish { reflection 0.7 } }
sphere { <-3, 1, 0.5>, 1 clipped_by { plane { y, 1.4 } } pigment { color rgb <0.9, 0.2, 0.2> } finish { F } }
sphere { <-1, 1, 0.5>, 0.9 bounded_by { box { <-2, 0, -0.5>, <0, 2, 1.5> } } pigment { color rgb <0.2, 0.8, 0.3> } finish { F } }
sphere { <1, 1, 0.5>, 0.8 no_shadow pigment { color rgb <0.2, 0.3, 0.9> } finish { F } }
sphere { <3, 1, 0.5>, 0.8 no_image pigment { color rgb <0.9, 0.8, 0.2> } finish { F } }
sphere { <-2, 0.7, -1.8>, 0.7 no_reflection pigment { color rgb <0.8, 0.4, 0.9> } finish { F } }
// A thin translucent sheet lit from behind: double_illuminate lights the front too.
box { <-0.5, 0, -0.01>, <0.5, 1.6, 0.01> rotate y*-150 translate <0.2, 0, -1.6> double_illuminate hollow
  pigment { color rgbt <0.3, 0.8, 0.8, 0.3> } finish { F } }
box { <-0.5, 0, -0.01>, <0.5, 1.6, 0.01> rotate y*-150 translate <1.6, 0, -1.6>
  pigment { color rgbt <0.3, 0.8, 0.8, 0.3> } finish { F } }
// Inverse of a whole difference, clipped to a sphere: a ball with the box shape carved away.
intersection { sphere { 0, 0.75 } difference { box { -0.5, 0.5 } sphere { <0.5, 0.5, -0.5>, 0.4 } inverse }
  rotate <15, 30, 0> translate <3, 0.8, -1.6> pigment { color rgb <1, 0.5, 0.1> } finish { F } }
