// Superellipsoids: a rounded box <0.25, 0.25>, a cushion <1, 0.2>, a pinched star <2.5, 2.5> under a rotation and non-uniform scale, a sphere-like <0.5, 1> and one cut by a difference.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
superellipsoid { <0.25, 0.25> translate <-3, 1, 1> pigment { color rgb <0.9, 0.2, 0.2> } finish { F } }
superellipsoid { <1, 0.2> scale <0.9, 0.5, 0.9> rotate <-20, 30, 0> translate <0, 1, 1.5> pigment { color rgb <0.2, 0.7, 0.3> } finish { F } }
superellipsoid { <2.5, 2.5> scale <1.2, 1, 0.9> rotate <10, 40, 15> translate <3, 1.1, 1> pigment { color rgb <0.2, 0.3, 0.9> } finish { F } }
superellipsoid { <0.5, 1> scale 0.8 rotate <0, -25, 0> translate <-1.6, 0.8, -1.6> pigment { color rgb <0.9, 0.8, 0.2> } finish { F } }
difference {
  superellipsoid { <0.3, 0.6> }
  sphere { <0, 0.6, -0.6>, 0.9 }
  scale 0.8 rotate <0, 20, 0> translate <1.5, 0.8, -1.8>
  pigment { color rgb <0.8, 0.4, 0.9> } finish { F }
}
