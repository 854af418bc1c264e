// Superellipsoids with exponents in the hundreds (e or n down to 0.002, as in advanced/benchmark's random ones): near-boxes and near-cylinders whose powers underflow inside and overflow outside unless computed from the larger coordinate.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
superellipsoid { <0.002, 0.002> scale 0.9 rotate <20, 35, 0> translate <-3, 1.2, 1> pigment { color rgb <0.9, 0.2, 0.2> } finish { F } }
superellipsoid { <1.6, 0.004> scale <0.9, 0.7, 0.9> rotate <-70, 30, 0> translate <0, 1.2, 1.5> pigment { color rgb <0.2, 0.7, 0.3> } finish { F } }
superellipsoid { <0.005, 1> scale 0.9 rotate <10, 40, 15> translate <3, 1.1, 1> pigment { color rgb <0.2, 0.3, 0.9> } finish { F } }
superellipsoid { <0.01, 2.5> scale 0.8 rotate <0, -25, 0> translate <-1.6, 0.9, -1.6> pigment { color rgb <0.9, 0.8, 0.2> } finish { F } }
superellipsoid { <2.6, 0.008> scale 0.8 rotate <30, 20, 0> translate <1.6, 0.9, -1.8> pigment { color rgb <0.8, 0.4, 0.9> } finish { F } }
