// material_map: an image whose pixels number the textures. POV-Ray's own palette image
// (povmap.png, found through the include path) picks one of four textures by its palette
// index; an 8-bit RGB image of this project's (scenes/images) picks by its red byte
// (numbers 0-5 over 3 textures: the count itself picks the last, larger ones wrap), once
// over part of a box face (the first texture beyond it), and map_type 1 wraps the palette
// image round a sphere; an 8-bit grey image (the hills) numbers a tile on the floor and a
// 16-bit grey one (the ridges) another
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6.5>
  look_at <0, 0.8, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

#declare Red = texture { pigment { rgb <0.8, 0.15, 0.1> } finish { ambient 0.15 diffuse 0.7 specular 0.4 } }
#declare Blue = texture { pigment { rgb <0.1, 0.2, 0.8> } finish { ambient 0.15 diffuse 0.7 } }
#declare Mirror = texture { pigment { rgb 0.2 } finish { ambient 0 diffuse 0.2 reflection 0.6 } }
#declare Stripes = texture { pigment { gradient y color_map { [0 rgb <1, 0.9, 0.3>] [1 rgb <0.2, 0.6, 0.2>] } scale 0.3 }
  finish { ambient 0.15 diffuse 0.7 } }

plane { y, 0 pigment { checker rgb 0.85 rgb 0.55 } finish { ambient 0.2 diffuse 0.7 } }
box { <-2.6, 0, 0>, <-0.6, 2, 0.2>
  texture { material_map { png "povmap.png" texture { Red } texture { Mirror } texture { Blue } texture { Stripes } }
    scale 2 translate <-2.6, 0, 0> }
}
sphere { <1.3, 1, 0.5>, 1
  texture { material_map { png "povmap.png" map_type 1 texture { Stripes } texture { Blue } texture { Red } texture { Mirror } } }
}
box { <-0.4, 0, -1.2>, <1.1, 1.3, -0.8>
  texture { material_map { png "images/material_numbers_rgb.png" once texture { Red } texture { Blue } texture { Stripes } }
    translate <-0.4, 0, 0> }
}
// An 8-bit grey image's numbers: its values cut as a bump map's heights are, then picked
// modulo the three textures (the hills' greys run 0 to 255)
box { <1.4, 0, -2>, <2.8, 0.05, -0.7>
  texture { material_map { png "images/hf_hills8.png" texture { Red } texture { Blue } texture { Stripes } }
    rotate x*90 scale 1.4 translate <1.4, 0, -2> }
}
// A 16-bit grey image's numbers: each value over 257, whole, then picked modulo the textures
box { <-2.8, 0, -2>, <-1.4, 0.05, -0.7>
  texture { material_map { png "images/hf_ridges16.png" texture { Red } texture { Blue } texture { Stripes } texture { Mirror } }
    rotate x*90 scale 1.4 translate <-2.8, 0, -2> }
}
