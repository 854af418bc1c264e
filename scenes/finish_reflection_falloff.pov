// Finish reflection {min, max falloff p}: the reflectivity grows from min head-on to max at
// grazing angles as (1-cos)^p, for falloff 1, 3 and 0.5 and a coloured min/max pair.
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
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb 0.1 } finish { diffuse 0.2 reflection { 0, 1 falloff 1 } } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb 0.1 } finish { diffuse 0.2 reflection { 0.1, 0.9 falloff 3 } } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb 0.1 } finish { diffuse 0.2 reflection { 0.05, 0.7 falloff 0.5 } } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb 0.1 } finish { diffuse 0.2 reflection { rgb <0.4, 0.1, 0>, rgb <0.2, 0.6, 1> falloff 2 } } }
