// projected_through: a light that reaches only what sees it through an object, as if it
// shone from there. A ring and a ball cast light shapes on the wall and the floor; a copy
// of them in the scene does not shadow that light, a box between the light and them does
// not either, and a small box between them and the wall does
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <3, 3, -10> look_at <-1, 2, 0> right x*image_width/image_height angle 55 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.1 diffuse 0.8 } }
plane { z, 0 pigment { rgb <0.3, 0.5, 0.7> } finish { ambient 0.1 diffuse 0.8 } }
#declare Stencil = union {
  torus { 0.8, 0.12 rotate x*90 }
  sphere { <0.3, 0.2, 0>, 0.25 }
  translate <-1, 3, -6>
}
object { Stencil pigment { rgb <0.8, 0.8, 0.2> } finish { ambient 0.2 diffuse 0.6 } }
box { <-1.2, 2.8, -8.6>, <-0.9, 3.3, -8.4> pigment { rgb <0.8, 0.2, 0.2> } }
box { <-0.2, 2.2, -2.2>, <0.2, 2.8, -2> pigment { rgb <0.2, 0.8, 0.2> } }
light_source { <-1, 3.5, -10> color rgb 2 projected_through { Stencil } }
light_source { <5, 8, -12> color rgb 0.3 }
