// Isosurfaces and user-defined functions: a bumpy sphere from a declared function with
// parameters, functions.inc's f_rounded_box cut by a sphere (difference), a rotated and
// stretched f_torus, an open wavy sheet cut by its box, and a floor coloured by a function
// pattern that calls a declared function.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -9> look_at <0, 0.6, 0> right x*image_width/image_height angle 48 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.35 }
#declare F = finish { phong 0.4 phong_size 30 }

#declare Bumps = function(a, b, k) { 0.08 * sin(k * a) * sin(k * b) }
#declare Ball = function { f_sphere(x, y, z, 0.9) + Bumps(x, y, 9) + Bumps(y, z, 7) }
isosurface {
  function { Ball(x, y, z) }
  contained_by { sphere { 0, 1.2 } }
  max_gradient 2.5
  translate <-2.6, 1.05, 0.5>
  pigment { color rgb <0.9, 0.45, 0.25> } finish { F }
}

difference {
  isosurface {
    function { f_rounded_box(x, y, z, 0.25, 0.9, 0.9, 0.9) }
    contained_by { box { -1, 1 } }
  }
  sphere { <0.3, 0.9, -0.9>, 0.75 }
  rotate <0, 35, 0>
  translate <0.2, 0.9, 1.2>
  pigment { color rgb <0.3, 0.6, 0.85> } finish { F }
}

isosurface {
  function { f_torus(x, y, z, 0.8, 0.28) }
  contained_by { box { <-1.1, -0.3, -1.1>, <1.1, 0.3, 1.1> } }
  scale <1, 1.4, 0.8>
  rotate <-60, 0, 20>
  translate <2.8, 1.1, 0.3>
  pigment { color rgb <0.4, 0.8, 0.35> } finish { F }
}

// Open: the sheet ends at its box, with no walls; select makes it a terrace.
isosurface {
  function { y - 0.15 * sin(3 * x) * cos(4 * z) - select(x, 0, 0.1) }
  contained_by { box { <-1.2, -0.4, -0.6>, <1.2, 0.4, 0.6> } }
  open
  max_gradient 1.8
  translate <0, 0.5, -2.2>
  pigment { color rgb <0.85, 0.8, 0.3> } finish { F }
}

#declare Rings = function { 0.5 + 0.5 * sin(2.5 * sqrt(x * x + z * z)) }
plane {
  y, 0
  pigment {
    function { Rings(x, y, z) * 0.8 + 0.1 }
    color_map { [0 color rgb <0.35, 0.35, 0.4>] [1 color rgb <0.75, 0.75, 0.7>] }
  }
}
