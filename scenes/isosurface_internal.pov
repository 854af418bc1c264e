// functions.inc's numbered internal functions as isosurfaces, left to right: a double
// f_helix1 with a diamond cross-section, an f_spiral seen from above, f_cross_ellipsoids
// and f_torus2, a field-strength surface (positive inside, so its strength is negative,
// and clamped to ±10 away from the surface); on a plane, under one light.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -7.5> look_at <0, 0.7, 0> right x*image_width/image_height angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
#declare F = finish { phong 0.3 phong_size 25 }

isosurface {
  function { f_helix1(x, y, z, 2, 4, 0.13, 0.42, 1, 2, 0) }
  contained_by { box { <-0.6, -1, -0.6>, <0.6, 1, 0.6> } }
  max_gradient 2.5
  translate <-2.7, 1, 0>
  pigment { color rgb <0.9, 0.5, 0.25> } finish { F }
}

isosurface {
  function { f_spiral(x, y, z, 0.25, 0.07, 1, 0, 0, 1) }
  contained_by { box { <-1, -0.1, -1>, <1, 0.1, 1> } }
  max_gradient 1.5
  rotate <-50, 0, 0>
  translate <-0.85, 0.95, 0>
  pigment { color rgb <0.35, 0.65, 0.9> } finish { F }
}

isosurface {
  function { f_cross_ellipsoids(x, y, z, 0.15, 3, 1, 0.5) }
  contained_by { box { -1, 1 } }
  max_gradient 1.5
  scale 0.7
  rotate <20, 30, 0>
  translate <0.85, 0.8, 0>
  pigment { color rgb <0.45, 0.8, 0.35> } finish { F }
}

isosurface {
  function { f_torus2(x, y, z, -0.25, 0.6, 0.22) }
  contained_by { box { <-0.9, -0.3, -0.9>, <0.9, 0.3, 0.9> } }
  max_gradient 1.5
  rotate <-60, 0, 0>
  translate <2.6, 0.85, 0>
  pigment { color rgb <0.85, 0.8, 0.3> } finish { F }
}

plane { y, 0 pigment { color rgb 0.7 } }
