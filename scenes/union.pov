// A union: children inherit the union's texture unless they have their own, and the
// union's transforms (non-uniform scale, rotation) move children and textures together.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <0.8, 0.9, 1> }

camera {
  location <0, 3, -7>
  look_at <0, 1, 0>
  right x*image_width/image_height
  angle 45
}
light_source {
  <4, 7, -3>
  color rgb 1
  area_light <1.5, 0, 0>, <0, 1.5, 0>, 4, 3 jitter
}

#declare Body = union {
  sphere { <0, 1, 0>, 1 }
  sphere { <0, 2.3, 0>, 0.6 pigment { color rgb <0.95, 0.9, 0.8> } }
  box { <-1.5, -0.1, -0.4>, <1.5, 0.3, 0.4> }
  pigment { checker color rgb <0.8, 0.1, 0.1> color rgb <0.1, 0.1, 0.8> scale 0.5 }
  finish { phong 0.5 }
}

object { Body scale <1, 0.8, 1> rotate y*25 translate <-1.2, 0, 0> }
object { Body scale 0.6 rotate <0, -40, 10> translate <1.8, 0.3, 0.5> }
plane { y, 0 pigment { color rgb <0.6, 0.7, 0.6> } }
