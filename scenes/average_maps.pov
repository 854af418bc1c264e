// average: normal_map (weighted unit normals) and texture_map (entries with their own
// finish and normal, weighted, and without weights)
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -10> look_at <0, 0, 0> right x*image_width/image_height angle 40 }
light_source { <-5, 6, -8> color rgb 0.8 }
light_source { <6, -2, -6> color rgb 0.4 }

#declare Thing = box { <-1.5, -1.5, 0>, <1.5, 1.5, 0.1> }
object { Thing
  texture { pigment { rgb 0.8 } finish { phong 0.8 phong_size 30 }
    normal { average normal_map {
      [1 gradient x, 0.8 triangle_wave scale 0.5]
      [2 gradient y, 0.6 scallop_wave scale 0.7] } } }
  translate <-1.7, 1.7, 0> }
object { Thing
  texture { average texture_map {
      [pigment { checker rgb <0.9,0.3,0.1>, rgb <0.1,0.2,0.6> scale 0.5 } finish { ambient 0.3 diffuse 0.5 }]
      [pigment { gradient x color_map { [0 rgb 1] [1 rgb <0.2,0.7,0.3>] } } finish { phong 1 phong_size 10 diffuse 0.7 } normal { onion 0.6 scale 0.3 }] } }
  translate <1.7, 1.7, 0> }
object { Thing
  texture { average texture_map {
      [3 pigment { rgb <0.9,0.8,0.2> } finish { ambient 0.2 }]
      [1 pigment { radial frequency 8 color_map { [0 rgb 0] [1 rgb <0.3,0.5,1>] } rotate x*90 } finish { specular 0.8 roughness 0.02 }] } }
  translate <-1.7, -1.7, 0> }
object { Thing
  texture { pigment { rgb <0.5,0.7,0.9> } finish { diffuse 0.8 phong 0.5 }
    normal { average normal_map {
      [gradient x, -1.5 scallop_wave scale 0.6]
      [onion 1 scale 0.4] } } }
  translate <1.7, -1.7, 0> }
