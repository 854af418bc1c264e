// CSG: union and merge (both glassy, so merge's missing inner walls show), intersection, difference, and inverse inside an intersection.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.3 } }
#declare Pair = union { sphere { <-0.45, 0, 0>, 0.8 } sphere { <0.45, 0, 0>, 0.8 } }
union { sphere { <-0.45, 0, 0>, 0.8 } sphere { <0.45, 0, 0>, 0.8 }
  translate <-2.6, 1, 1> pigment { color rgbt <0.9, 0.5, 0.5, 0.6> } finish { F } }
merge { sphere { <-0.45, 0, 0>, 0.8 } sphere { <0.45, 0, 0>, 0.8 }
  translate <0, 1, 1> pigment { color rgbt <0.5, 0.9, 0.5, 0.6> } finish { F } }
intersection { box { -0.7, 0.7 } sphere { 0, 0.9 }
  rotate <20, 30, 0> translate <2.6, 1, 1> pigment { color rgb <0.3, 0.4, 0.9> } finish { F } }
difference { box { -0.7, 0.7 } sphere { 0, 0.9 } cylinder { <0, 0, -1>, <0, 0, 1>, 0.3 }
  rotate <20, -30, 0> translate <-1.6, 0.9, -1.8> pigment { color rgb <0.9, 0.7, 0.2> } finish { F } }
intersection { sphere { 0, 0.9 } cylinder { <-1, 0, 0>, <1, 0, 0>, 0.45 inverse }
  rotate <0, 40, 20> translate <1.4, 0.9, -1.8> pigment { color rgb <0.8, 0.3, 0.8> } finish { F } }
