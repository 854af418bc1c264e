// Julia fractals: quaternion sqr and cube, and a quaternion one cut open by a box in a
// difference, each under its own scale and rotation. Hypercomplex ones are left out: POV-Ray
// misses parts of them that its own inside test holds (docs/language.md, julia_fractal).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
julia_fractal {
  <-0.083, 0.0, -0.83, -0.025>
  quaternion sqr
  max_iteration 8
  precision 20
  scale 1.0 rotate <0, 30, 0> translate <-3, 1.1, 1>
  pigment { color rgb <0.9, 0.2, 0.2> } finish { F }
}
julia_fractal {
  <-0.03, 0.5, -0.2, -0.5>
  quaternion cube
  max_iteration 8
  precision 30
  scale 1.2 rotate <20, -40, 0> translate <0, 1.2, 1.5>
  pigment { color rgb <0.2, 0.7, 0.3> } finish { F }
}
difference {
  julia_fractal {
    <-0.2, 0.6, 0.2, 0.0>
    quaternion sqr
    max_iteration 9
    precision 40
  }
  box { <-2, -2, -2>, <2, 2, -0.1> }
  scale 0.9 rotate <0, -25, 0> translate <-0.6, 1, -2.2>
  pigment { color rgb <0.9, 0.8, 0.2> } finish { F }
}
