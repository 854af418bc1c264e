// Blobs: spheres melting together (their textures mixing where they meet, a component without one showing the blob's), cylinders with round ends and a negative component cutting a dent, a component under its own scale and rotation, a blob transformed as a whole, and one inside a difference.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
blob {
  threshold 0.6
  sphere { <-0.5, 0, 0>, 1, 1 texture { pigment { color rgb <0.95, 0.85, 0.1> } finish { F } } }
  sphere { <0.5, 0.1, 0>, 1, 1 texture { pigment { color rgb <0.1, 0.3, 0.95> } finish { F } } }
  sphere { <0, 0.8, 0.2>, 0.8, strength 1.5 }
  translate <-3, 1, 1>
  pigment { color rgb <0.9, 0.2, 0.2> } finish { F }
}
blob {
  threshold 0.5
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.6, 2 }
  cylinder { <0, -0.2, -0.6>, <0, 1.4, 0.3>, 0.5, 1.5 }
  sphere { <0.5, 0.4, -0.5>, 0.5, -3 pigment { color rgb <0.9, 0.9, 0.9> } finish { F } }
  translate <0, 0.6, 1.5>
  pigment { color rgb <0.2, 0.7, 0.3> } finish { F }
}
blob {
  threshold 0.4
  sphere { <0, 0, 0>, 1, 1 scale <1.6, 0.6, 0.8> rotate <0, 0, 30> }
  sphere { <0.6, 0.6, 0>, 0.7, 1 }
  component 1, 0.8, <-0.6, -0.3, 0>
  scale <0.9, 1.1, 1> rotate <20, 40, 0> translate <3, 1, 1>
  pigment { color rgb <0.2, 0.3, 0.9> } finish { F }
}
difference {
  blob {
    threshold 0.3
    sphere { <-0.4, 0, 0>, 1, 1 }
    sphere { <0.4, 0, 0>, 1, 1 }
  }
  box { <-2, 0.2, -2>, <2, 2, -0.1> }
  rotate <0, -20, 0> translate <-1.3, 0.8, -1.7>
  pigment { color rgb <0.9, 0.8, 0.2> } finish { F }
}
intersection {
  blob {
    threshold 0.5
    sphere { <0, 0, 0>, 1.2, 1 }
    cylinder { <0, -1, 0>, <0, 1, 0>, 0.5, -1 }
  }
  sphere { <0, 0, 0>, 0.62 }
  rotate <-30, 0, 0> translate <1.6, 0.75, -1.8>
  pigment { color rgb <0.8, 0.4, 0.9> } finish { F }
}
