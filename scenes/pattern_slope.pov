// slope patterns: the normal's turn towards a direction (a terrain-like texture_map chosen
// by it, as advanced/balcony does), the perturbed normal read by slope, slope with its own
// range, and slope mixed with altitude (weights by the vectors' lengths), under transforms
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

#declare Grass = texture { pigment { rgb <0.2, 0.5, 0.1> } finish { ambient 0.15 diffuse 0.7 } }
#declare Rock = texture { pigment { rgb <0.6, 0.55, 0.5> } finish { ambient 0.15 diffuse 0.7 specular 0.2 } }

plane { y, 0 pigment { slope { x, 0.4, 0.6 } color_map { [0 rgb 0.2] [1 rgb 0.9] } }
  normal { waves 0.6 scale 0.4 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.4, 1, 0>, 1
  texture { slope y texture_map { [0.6 Rock] [0.6 Grass] } }
}
torus { 0.6, 0.3 rotate x*60 translate <0.2, 0.9, 0.6>
  texture {
    pigment { slope { y*2 altitude y, 0.6, 1.2 } color_map { [0 rgb <0.8, 0.2, 0.1>] [1 rgb <1, 1, 0.6>] } }
    normal { waves 0.8 scale 0.2 }
    finish { ambient 0.15 diffuse 0.7 }
  }
}
box { <-0.5, 0, -0.5>, <0.5, 1.2, 0.5> rotate y*30 translate <1.8, 0, -0.3>
  pigment { slope { -z } rotate z*40 color_map { [0 rgb <0, 0.3, 0.8>] [0.5 rgb 1] [1 rgb <0.9, 0.6, 0.1>] } }
  finish { ambient 0.2 diffuse 0.7 }
}
