// mesh2: a closed octahedron with a texture per face (texture_list) and an inside_vector,
// cut by a sphere in a difference and intersected with a box; a smooth saddle with
// normal_vectors and normal_indices; a quad with uv_vectors under a uv_mapping checker; a
// face whose corners each name a texture (the colours mix); transforms throughout.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.9, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
#declare Gem = mesh2 {
  vertex_vectors { 6, <1, 0, 0>, <-1, 0, 0>, <0, 1.2, 0>, <0, -1.2, 0>, <0, 0, 1>, <0, 0, -1> }
  texture_list { 3,
    texture { pigment { color rgb <0.9, 0.2, 0.2> } finish { F } }
    texture { pigment { color rgb <0.2, 0.4, 0.9> } finish { F } }
    texture { pigment { color rgb <0.9, 0.8, 0.2> } finish { F } }
  }
  face_indices { 8,
    <0, 2, 4>, 0, <4, 2, 1>, 1, <1, 2, 5>, 2, <5, 2, 0>, 0,
    <0, 4, 3>, 1, <4, 1, 3>, 2, <1, 5, 3>, 0, <5, 0, 3>, 1
  }
  inside_vector <0, 0, 1>
}
object { Gem rotate <0, 30, 0> translate <-3.2, 1.3, 0.5> }
difference {
  object { Gem }
  sphere { <0, 0.6, -0.7>, 0.75 }
  rotate <0, -25, 0> translate <-0.6, 1.3, -1.4>
  pigment { color rgb <0.8, 0.5, 0.9> } finish { F }
}
intersection {
  object { Gem scale 1.2 }
  box { <-2, -0.5, -2>, <2, 0.7, 2> }
  rotate <20, 40, 0> translate <1.6, 1.0, -2.2>
  pigment { color rgb <0.3, 0.8, 0.5> } finish { F }
}
// A saddle y = x z over [-1, 1]^2 on a 3 x 3 grid, smooth.
mesh2 {
  vertex_vectors { 9,
    <-1, 1, -1>, <0, 0, -1>, <1, -1, -1>,
    <-1, 0, 0>, <0, 0, 0>, <1, 0, 0>,
    <-1, -1, 1>, <0, 0, 1>, <1, 1, 1>
  }
  normal_vectors { 9,
    <1, 1, 1>, <1, 1, 0>, <1, 1, -1>,
    <0, 1, 1>, <0, 1, 0>, <0, 1, -1>,
    <-1, 1, 1>, <-1, 1, 0>, <-1, 1, -1>
  }
  face_indices { 8,
    <0, 1, 4>, <0, 4, 3>, <1, 2, 5>, <1, 5, 4>,
    <3, 4, 7>, <3, 7, 6>, <4, 5, 8>, <4, 8, 7>
  }
  normal_indices { 8,
    <0, 1, 4>, <0, 4, 3>, <1, 2, 5>, <1, 5, 4>,
    <3, 4, 7>, <3, 7, 6>, <4, 5, 8>, <4, 8, 7>
  }
  pigment { color rgb <0.9, 0.6, 0.3> } finish { F }
  scale <1.1, 0.5, 1.1> rotate <-25, 65, 0> translate <2.9, 1.6, 1.6>
}
// A quad with uvs under a checker, and a triangle whose corners have their own textures.
mesh2 {
  vertex_vectors { 5, <0, 0, 0>, <2, 0, 0>, <2, 2, 0>, <0, 2, 0>, <1, 3.2, 0> }
  uv_vectors { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0.5, 1.6> }
  texture_list { 3,
    texture { pigment { color rgb <1, 0.1, 0.1> } }
    texture { pigment { color rgb <0.1, 1, 0.1> } }
    texture { pigment { color rgb <0.1, 0.1, 1> } }
  }
  face_indices { 3, <0, 1, 2>, <0, 2, 3>, <3, 2, 4>, 0, 1, 2 }
  texture { uv_mapping pigment { checker color rgb 1, color rgb 0.1 scale 0.25 } }
  rotate <0, -15, 0> translate <0.6, 0.2, 2.5>
}
