// Finish metallic on phong and on specular: the highlight takes the pigment's colour, less
// so towards grazing light (bare `metallic`, metallic 0.5, and without it for comparison).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 6, -5> color rgb 1 }
light_source { <6, 0.8, 2> color rgb <0.8, 0.8, 0.8> }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.3, 0.3, 0.3> } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <1, 0.6, 0.1> } finish { diffuse 0.3 phong 1 phong_size 8 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <1, 0.6, 0.1> } finish { diffuse 0.3 phong 1 phong_size 8 metallic } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb <0.2, 0.5, 1> } finish { diffuse 0.3 specular 1 roughness 0.1 metallic 0.5 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.2, 0.5, 1> } finish { diffuse 0.3 specular 1 roughness 0.1 metallic } }
