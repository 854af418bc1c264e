// Every analytic shape: sphere, plane, box, cylinder (closed and open), cone (closed and open), disc with a hole, torus.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
sphere { <-3, 1, 1>, 1 pigment { color rgb <0.9, 0.2, 0.2> } finish { F } }
box { <-1.5, 0, 0.5>, <-0.3, 1.4, 1.7> pigment { color rgb <0.2, 0.7, 0.3> } finish { F } }
cylinder { <0.5, 0, 1>, <1.2, 1.8, 1.4>, 0.5 pigment { color rgb <0.2, 0.3, 0.9> } finish { F } }
cylinder { <2.2, 0.2, 0.2>, <3.4, 1.2, 1.2>, 0.5 open pigment { color rgb <0.9, 0.8, 0.2> } finish { F } }
cone { <-3, 0, -2>, 0.8, <-2.6, 1.6, -1.6>, 0.2 pigment { color rgb <0.8, 0.4, 0.9> } finish { F } }
cone { <-1.2, 0.3, -1.8>, 0.1, <-0.8, 1.3, -1.4>, 0.7 open pigment { color rgb <0.3, 0.8, 0.8> } finish { F } }
disc { <0.8, 0.9, -1.5>, <0.3, 1, -0.6>, 0.9, 0.35 pigment { color rgb <1, 0.5, 0.1> } finish { F } }
torus { 0.8, 0.25 rotate <-30, 0, 20> translate <2.8, 1.0, -1.4> pigment { color rgb <0.7, 0.7, 0.7> } finish { F } }
