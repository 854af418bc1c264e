// area_illumination: a wide 7x3 area light close to the objects, shading summed over its
// grid points; the irregular 7-point weights and jitter in one light.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3.5, -6>
  look_at <0, 0.5, 0>
  right x*image_width/image_height
  angle 50
}
light_source {
  <0, 2.5, -0.5> color rgb 1
  area_light <5, 0, 0>, <0, 0, 1.5>, 7, 3
  jitter
  area_illumination on
}

plane { y, 0 pigment { color rgb 0.8 } }
sphere { <-1.3, 0.6, 0.3>, 0.6 pigment { color rgb <0.9, 0.5, 0.2> } finish { phong 0.7 phong_size 20 } }
box { <0.5, 0, -0.2>, <1.8, 0.9, 0.9> pigment { color rgb <0.3, 0.5, 0.9> } finish { specular 0.5 roughness 0.1 } }
