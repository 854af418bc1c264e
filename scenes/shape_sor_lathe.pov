// sor (closed and open) and lathe (linear, quadratic, cubic, bezier splines), one of each in CSG, one transformed
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 4.5, -7>
  look_at <0, 0.7, 0.3>
  right x*image_width/image_height
  angle 48
}
light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 6, -3> color rgb 0.4 }

plane { y, 0 pigment { checker rgb 0.25, rgb 0.7 } finish { ambient 0.2 diffuse 0.7 } }

// A vase, closed, and an open one seen into.
sor { 6, <0.2, -0.3>, <0.5, 0.01>, <0.9, 0.6>, <0.3, 1.2>, <0.6, 1.8>, <1.0, 2.5>
  pigment { rgb <0.9, 0.5, 0.2> } finish { phong 0.5 } scale 0.7 translate <-2.4, 0, 1.4> }
sor { 5, <0.0, -0.5>, <0.6, 0.0>, <0.3, 0.6>, <0.7, 1.2>, <0.8, 1.5> open
  pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.3 } scale 0.8 translate <-0.6, 0, 1.8> }
// Lathes: a linear ring with a square section, a quadratic and a cubic bowl, a bezier bulb.
lathe { linear_spline 5, <0.5, 0>, <0.8, 0>, <0.8, 0.4>, <0.5, 0.4>, <0.5, 0>
  pigment { rgb <0.9, 0.8, 0.2> } finish { specular 0.4 } translate <1.2, 0, 1.8> }
lathe { quadratic_spline 6, <0, 0>, <0.01, 0>, <0.6, 0.1>, <0.8, 0.6>, <0.7, 0.6>, <0.5, 0.15>
  pigment { rgb <0.3, 0.5, 0.95> } finish { phong 0.6 } translate <2.8, 0, 1.0> }
lathe { cubic_spline 7, <0, -0.2>, <0.01, 0>, <0.5, 0.05>, <0.7, 0.5>, <0.6, 0.9>, <0.01, 1.0>, <0, 1.1>
  pigment { rgb <0.8, 0.4, 0.9> } translate <-2.2, 0, -0.8> }
lathe { bezier_spline 8,
  <0.0, 0.0>, <0.6, 0.0>, <0.8, 0.5>, <0.4, 0.8>,
  <0.4, 0.8>, <0.1, 1.0>, <0.3, 1.3>, <0.0, 1.4>
  pigment { rgb <0.95, 0.6, 0.6> } finish { phong 0.4 } translate <-0.5, 0, -0.7> }
// A box minus a sor, and a sphere cut by a lathe.
difference {
  box { <-0.6, 0, -0.6>, <0.6, 0.8, 0.6> }
  sor { 4, <0.2, -0.5>, <0.4, 0.1>, <0.2, 0.9>, <0.4, 1.5> }
  pigment { rgb <0.85, 0.85, 0.85> } finish { phong 0.3 }
  translate <1.1, 0, -0.8>
}
intersection {
  sphere { <0, 0.5, 0>, 0.55 }
  lathe { cubic_spline 6, <0.1, -0.2>, <0.2, 0>, <0.5, 0.4>, <0.2, 0.8>, <0.2, 0>, <0.5, 0.4> }
  pigment { rgb <0.2, 0.8, 0.8> } translate <2.7, 0, -0.6>
}
// Transformed: a lathe ring tipped over.
lathe { linear_spline 4, <0.3, -0.1>, <0.45, 0>, <0.3, 0.1>, <0.3, -0.1>
  pigment { rgb <1, 0.3, 0.3> } rotate <70, 0, 30> scale <1, 1.3, 1> translate <0.3, 0.6, 0.6> }
