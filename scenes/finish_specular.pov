// Finish specular and roughness (Blinn half-vector highlight): roughness 0.2 to 0.002 and
// `specular albedo` (normalised by the roughness exponent), under two lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 6, -5> color rgb 1 }
light_source { <5, 2, -3> color rgb <0.4, 0.5, 0.7> }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.3, 0.3, 0.3> } finish { specular 0.4 roughness 0.1 } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <0.2, 0.1, 0.1> } finish { specular 0.5 roughness 0.2 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <0.1, 0.2, 0.1> } finish { specular 1 } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb <0.1, 0.1, 0.2> } finish { specular 0.8 roughness 0.002 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.2, 0.2, 0.1> } finish { specular albedo 0.1 roughness 0.02 } }
