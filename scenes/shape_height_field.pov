// Height fields from an 8-bit and a 16-bit grey PNG (scenes/images, made by
// scripts/make_hf_images.py): flat-shaded and smooth, one with a water level, one cut by a
// sphere in a difference and one intersected with a box, all scaled, turned and moved; and
// two from functions (a float function calling a declared one, and a pigment's grey).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.6, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.3 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
height_field {
  png "images/hf_hills8.png"
  translate <-0.5, 0, -0.5> scale <3, 1.6, 3> rotate <0, 25, 0> translate <-2.6, 0, 1.2>
  pigment { color rgb <0.85, 0.45, 0.25> } finish { F }
}
height_field {
  png "images/hf_ridges16.png" smooth
  translate <-0.5, 0, -0.5> scale <3.2, 1.2, 2.6> rotate <0, -20, 0> translate <2.4, 0, 1.5>
  pigment { gradient y color_map { [0 color rgb <0.2, 0.4, 0.9>] [1 color rgb <0.9, 0.9, 0.9>] } scale 1.2 }
  finish { F }
}
height_field {
  png "images/hf_hills8.png" smooth water_level 0.2
  translate <-0.5, 0, -0.5> scale <2.2, 1.4, 2.2> translate <0.2, 0.01, -1.2>
  pigment { color rgb <0.3, 0.75, 0.35> } finish { F }
}
difference {
  height_field { "images/hf_ridges16.png" }
  sphere { <0.5, 0.9, 0.3>, 0.35 }
  translate <-0.5, 0, -0.5> scale <1.8, 1.2, 1.8> rotate <0, 40, 0> translate <-2.7, 0, -2.2>
  pigment { color rgb <0.8, 0.5, 0.9> } finish { F }
}
intersection {
  height_field { png "images/hf_ridges16.png" smooth }
  box { <0.15, -1, 0.1>, <0.85, 2, 0.7> }
  translate <-0.5, 0, -0.5> scale <2, 1.4, 2> rotate <0, -35, 0> translate <2.6, 0, -2.3>
  pigment { color rgb <0.9, 0.8, 0.2> } finish { F }
}
#declare Ripple = function(a, b) { 0.5 + 0.3 * sin(a * 9) * cos(b * 7) }
height_field {
  function 48, 40 { Ripple(x, y) + 0.1 * x } smooth
  translate <-0.5, 0, -0.5> scale <2.6, 0.9, 1.6> translate <0, 0, 3.6>
  pigment { color rgb <0.95, 0.6, 0.6> } finish { F }
}
height_field {
  function 32, 32 { pigment { gradient x color_map { [0 rgb 0.1] [0.6 rgb 0.9] [1 rgb 0.3] } } }
  translate <-0.5, 0, -0.5> scale <1.4, 0.8, 1.2> rotate <0, 15, 0> translate <0.1, 0, 1.2>
  pigment { color rgb <0.5, 0.8, 0.9> } finish { F }
}
