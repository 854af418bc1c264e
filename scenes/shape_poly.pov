// Algebraic surfaces: a cubic (monkey saddle) clipped to a box, a sextic rounded cube with a
// mixed term under rotation and scale, a quartic written in the polynomial syntax (a tangle
// cube), and an unbounded quintic inside an intersection with a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
// y = x^3 - 3 x z^2.
cubic {
  <
    1, 0, 0, 0, 0, 0, 0, -3, 0, 0, 0, 0,
    0, 0, 0, -1, 0, 0, 0, 0
  >
  sturm
  clipped_by { box { -1, 1 } }
  bounded_by { box { -1, 1 } }
  scale 0.9 rotate <0, 20, 0> translate <-3, 1.2, 1>
  pigment { color rgb <0.9, 0.2, 0.2> } finish { F }
}
// x^6 + y^6 + z^6 + 6 x^2 y^2 z^2 = 1.
poly {
  6,
  <
    1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 6,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1
  >
  bounded_by { sphere { 0, 1.8 } }
  scale <0.9, 0.7, 0.8> rotate <25, 35, 10> translate <0, 1, 1.5>
  pigment { color rgb <0.2, 0.7, 0.3> } finish { F }
}
// A tangle cube: x^4 - 5 x^2 + y^4 - 5 y^2 + z^4 - 5 z^2 + 11.8 = 0.
polynomial {
  4,
  xyz(4, 0, 0): 1, xyz(2, 0, 0): -5,
  xyz(0, 4, 0): 1, xyz(0, 2, 0): -5,
  xyz(0, 0, 4): 1 xyz(0, 0, 2): -5
  xyz(0, 0, 0): 11.8
  sturm
  bounded_by { sphere { 0, 4 } }
  scale 0.33 rotate <0, -30, 0> translate <3, 1.1, 1>
  pigment { color rgb <0.2, 0.3, 0.9> } finish { F }
}
// x^4 + y^4 + z^4 + 0.6 x^5 + 0.3 y^2 = 1: a second sheet far along -x, cut away by the
// sphere.
intersection {
  poly {
    5,
    <
    0.6, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 1, 0, 0, 0, 0, 0, 0, 0.3, 0, 0, 0,
    0, 0, 0, 1, 0, 0, 0, -1
  >
  }
  sphere { 0, 1.05 }
  scale 0.75 rotate <0, -40, 0> translate <-1.5, 0.75, -2>
  pigment { color rgb <0.9, 0.8, 0.2> } finish { F }
}
// The sextic again, with a bite taken out by a sphere; bounded, as scenes bound polys.
difference {
  poly {
    6,
    <
    1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 6,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1
  >
    bounded_by { sphere { 0, 1.3 } }
  }
  sphere { <0.6, 0.6, -0.6>, 0.7 }
  scale 0.6 rotate <0, 30, 0> translate <1.7, 0.6, -1.9>
  pigment { color rgb <0.8, 0.4, 0.9> } finish { F }
}
