// Quadric (a hyperboloid clipped to a box and an ellipsoid), triangle, smooth_triangle, mesh with inside_vector in CSG, and polygon with a hole.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.15
  clipped_by { box { <-1, 0, -1>, <1, 1.6, 1> } }
  translate <-3, 0, 1> pigment { color rgb <0.9, 0.3, 0.2> } finish { F } }
quadric { <1, 4, 2>, <0, 0, 0>, <0, 0, 0>, -1 translate <-3, 0.6, -1.8> pigment { color rgb <0.2, 0.5, 0.9> } finish { F } }
triangle { <-1.5, 0, 0.5>, <0, 2, 1.5>, <0.5, 0.2, 0> pigment { color rgb <0.2, 0.8, 0.3> } finish { F } }
smooth_triangle { <0.5, 0, 1>, <-0.5, 0.3, -1>, <2, 2, 1.8>, <0.5, 0.3, -1>, <1.5, 0, 0>, <0.3, 0.5, -1>
  pigment { color rgb <0.9, 0.8, 0.2> } finish { phong 0.6 } }
#declare Tetra = mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 0, 1> }
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  triangle { <0, 0, 0>, <0, 1, 0>, <0, 0, 1> }
  triangle { <1, 0, 0>, <0, 1, 0>, <0, 0, 1> }
  inside_vector <1, 2, 3>
}
difference {
  object { Tetra scale 1.8 }
  sphere { <0, 0, 0>, 0.8 }
  rotate y*200 translate <3.2, 0, 0.6>
  pigment { color rgb <0.8, 0.4, 0.9> } finish { F }
}
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0.5, 1, 0> }
  triangle { <1, 0, 0>, <0.5, 1, 0>, <1.2, 0.9, 0.8> }
  scale 1.2 rotate y*-20 translate <-1.2, 0.1, -1.8> pigment { color rgb <0.3, 0.8, 0.8> } finish { F }
}
polygon { 9, <0, 0>, <2, 0>, <2, 2>, <0, 2>, <0, 0>, <0.5, 0.5>, <1.5, 0.5>, <1, 1.6>, <0.5, 0.5>
  rotate x*-30 translate <1.2, 0.2, -2> pigment { color rgb <1, 0.5, 0.1> } finish { F } }
