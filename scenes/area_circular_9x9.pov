// Smooth quadrics under a 9x9 circular, oriented area light: POV-Ray computes the whole
// grid at every shading point; the equal-error benchmark at 640x480 starts from this scene.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.7, 0> right x*image_width/image_height angle 45 }
light_source { <-3, 7, -3> color rgb 1 area_light <3, 0, 0>, <0, 0, 3>, 9, 9 circular orient }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.75> } finish { diffuse 0.8 } }
sphere { <-1.2, 1, 0.5>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
cylinder { <1.2, 0, 0>, <1.2, 1.6, 0>, 0.6 pigment { color rgb <0.2, 0.5, 0.9> } }
cone { <0, 0, -1.6>, 0.6, <0, 1.1, -1.6>, 0 pigment { color rgb <0.3, 0.8, 0.3> } }
