// Transforms: object copies with their own modifiers, non-uniform and negative scale, matrix, transform blocks and transform inverse.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
#declare Thing = union {
  box { <-0.5, 0, -0.3>, <0.5, 0.6, 0.3> }
  cone { <0, 0.6, 0>, 0.4, <0.3, 1.2, 0>, 0.1 }
  pigment { checker color rgb <0.9, 0.2, 0.2> color rgb <0.9, 0.9, 0.9> scale 0.2 }
  finish { F }
}
#declare Move = transform { rotate y*35 translate <0.5, 0, 0> }
object { Thing translate <-3, 0, 1> }
object { Thing scale <1.5, 0.6, 1> rotate y*30 translate <-1, 0, 1> pigment { color rgb <0.2, 0.8, 0.3> } }
object { Thing scale <-1, 1, 1> translate <1, 0, 1> }
object { Thing scale <1, -1, 1> translate <3, 1.2, 1> }
object { Thing matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> translate <-3, 0, -1.8> }
object { Thing transform { Move } translate <-1.5, 0, -1.8> }
object { Thing transform { Move } transform { Move inverse } translate <1, 0, -1.8> }
torus { 0.5, 0.15 scale <1, 2, 0.6> rotate <60, 0, 30> translate <3, 0.8, -1.8> pigment { color rgb <0.8, 0.4, 0.9> } finish { F } }
