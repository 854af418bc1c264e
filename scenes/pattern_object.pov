// The object pattern: a pigment, a texture and a normal chosen by whether the point is
// inside an object (entry 1) or outside it (entry 0), the object in the pattern's own
// space, moved by the pattern's transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6.5> look_at <0, 0.6, 0> angle 48 }
light_source { <-6, 12, -9> color rgb 1 }
light_source { <6, 5, -8> color rgb 0.35 shadowless }
#declare Mark = union {
  box { <-0.25, -1, -1>, <0.25, 1, 1> }
  difference {
    cylinder { <0, -1, 0>, <0, 1, 0>, 1.1 }
    cylinder { <0, -2, 0>, <0, 2, 0>, 0.8 }
  }
}
plane {
  y, 0
  pigment {
    object { Mark color rgb <0.85, 0.75, 0.35>, color rgb <0.15, 0.25, 0.6> }
    scale 1.3 rotate y * 25 translate <0.3, 0, -2.2>
  }
}
sphere {
  <-1.3, 1, 0>, 1
  texture {
    object {
      torus { 0.8, 0.3 rotate x * 90 }
      texture { pigment { rgb 0.9 } finish { phong 0.6 } },
      texture { pigment { checker rgb <0.8, 0.1, 0.1> rgb <0.3, 0, 0> scale 0.2 } }
    }
    rotate y * 40 translate <-1.3, 1, -0.2>
  }
}
box {
  <0.4, 0, -0.9>, <2.2, 1.8, 0.9>
  pigment { object { sphere { 0, 1 } } scale 0.8 translate <1.3, 0.9, -0.9> }
  normal { object { sphere { 0, 1 } normal { leopard 0.8 scale 0.08 }, normal { gradient x 0.5 scale 0.3 } } scale 0.7 translate <1.3, 1.8, 0> }
}
