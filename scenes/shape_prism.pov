// prism: linear, quadratic, cubic and bezier splines, a conic sweep, an open one, one in a difference and one transformed
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 5, -7>
  look_at <0, 0.4, 0.3>
  right x*image_width/image_height
  angle 48
}
light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 6, -3> color rgb 0.4 }

plane { y, 0 pigment { checker rgb 0.25, rgb 0.7 } finish { ambient 0.2 diffuse 0.7 } }

#declare Star = prism {
  linear_sweep linear_spline 0, 0.6, 11,
  <0.2, -1.0>, <0.2, 0.2>, <1.0, -0.2>, <1.0, 0.2>, <0.2, 1.0>,
  <-0.2, 1.0>, <-1.0, 0.2>, <-1.0, -0.2>, <-0.2, 0.2>, <-0.2, -1.0>,
  <0.2, -1.0>
}
// A linear prism with a square hole (two sub-polygons, even-odd).
prism { linear_spline 0, 0.5, 10,
  <-0.6, -0.6>, <0.6, -0.6>, <0.6, 0.6>, <-0.6, 0.6>, <-0.6, -0.6>,
  <-0.3, -0.3>, <0.3, -0.3>, <0.3, 0.3>, <-0.3, 0.3>, <-0.3, -0.3>
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 }
  rotate y*20 translate <-2.4, 0, 1.2>
}
object { Star pigment { rgb <0.9, 0.8, 0.2> } finish { specular 0.4 } translate <-0.6, 0, 1.6> scale 0.8 }
prism { quadratic_spline 0, 0.7, 12,
  <0.2, -1.0>, <0.2, 0.2>, <1.0, -0.2>, <1.0, 0.2>, <0.2, 1.0>,
  <-0.2, 1.0>, <-1.0, 0.2>, <-1.0, -0.2>, <-0.2, 0.2>, <-0.2, -1.0>,
  <0.2, -1.0>, <0.2, 0.2>
  pigment { rgb <0.3, 0.8, 0.3> } scale 0.7 translate <1.0, 0, 1.5>
}
prism { cubic_spline 0, 0.8, 13,
  <-0.2, -1.0>,
  <0.2, -1.0>, <0.2, 0.2>, <1.0, -0.2>, <1.0, 0.2>, <0.2, 1.0>,
  <-0.2, 1.0>, <-1.0, 0.2>, <-1.0, -0.2>, <-0.2, 0.2>, <-0.2, -1.0>,
  <0.2, -1.0>, <0.2, 0.2>
  pigment { rgb <0.3, 0.5, 0.95> } finish { phong 0.6 } scale 0.7 translate <2.6, 0, 0.8>
}
// Bezier: a rounded lens and a leaf, two sub-shapes.
prism { bezier_spline 0, 0.5, 16,
  <-0.8, 0>, <-0.4, 0.9>, <0.4, 0.9>, <0.8, 0>,
  <0.8, 0>, <0.4, -0.9>, <-0.4, -0.9>, <-0.8, 0>,
  <-0.3, 0>, <-0.1, 0.3>, <0.1, 0.3>, <0.3, 0>,
  <0.3, 0>, <0.1, -0.3>, <-0.1, -0.3>, <-0.3, 0>
  pigment { rgb <0.8, 0.4, 0.9> } translate <-2.4, 0, -0.8>
}
// Conic sweep: the profile scaled by y, a frustum upside down on the floor.
prism { conic_sweep linear_spline 0.4, 1, 5,
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  pigment { rgb <0.95, 0.6, 0.2> } finish { phong 0.4 }
  translate -y*1 scale <0.6, -1.2, 0.6> translate <-0.4, 0, -0.6>
}
// A difference: a box minus a cubic prism, showing the prism's inside.
difference {
  box { <-0.6, 0, -0.6>, <0.6, 0.7, 0.6> }
  prism { cubic_spline -0.1, 0.8, 7,
    <0, -0.4>, <0.4, 0>, <0, 0.4>, <-0.4, 0>, <0, -0.4>, <0.4, 0>, <0, 0.4> }
  pigment { rgb <0.85, 0.85, 0.85> } finish { phong 0.3 }
  translate <1.1, 0, -0.9>
}
// Transformed and open: the star on its side, tilted.
prism { linear_sweep linear_spline 0, 0.6, 11,
  <0.2, -1.0>, <0.2, 0.2>, <1.0, -0.2>, <1.0, 0.2>, <0.2, 1.0>,
  <-0.2, 1.0>, <-1.0, 0.2>, <-1.0, -0.2>, <-0.2, 0.2>, <-0.2, -1.0>,
  <0.2, -1.0>
  open pigment { rgb <0.2, 0.8, 0.8> } scale 0.45 rotate <80, 30, 0> translate <2.7, 0.55, -0.8> }
