// Finish reflection, plain: a grey amount, a coloured amount, and the full mirror, on
// spheres that reflect a checkered floor, a back wall, the sky and a wall behind the camera.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 6, -5> color rgb 1 }
background { color rgb <0.2, 0.3, 0.6> }

plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.2, 0.3, 0.2> scale 1.5 } }
plane { z, 5 pigment { color rgb <0.9, 0.4, 0.2> } }
box { <-4, 0, -9>, <4, 3, -8.5> pigment { color rgb <0.3, 0.7, 0.4> } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <0.8, 0.8, 0.8> } finish { diffuse 0.3 reflection 0.4 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <0.2, 0.2, 0.2> } finish { diffuse 0.2 reflection rgb <0.9, 0.5, 0.2> } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.4, 0.3, 0.8> } finish { reflection { 0.3 } } }
