// Textures as the entries of list patterns (a checker floor of two finishes, a hexagon
// sphere of three textures) and an average pigment_map with and without weights
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -5> look_at <0, 0.5, 0> right x*image_width/image_height angle 50 }
light_source { <-4, 6, -5> color rgb 1 }

#declare Shiny = texture { pigment { rgb <0.8, 0.3, 0.2> } finish { phong 0.8 ambient 0.1 } }
plane { y, 0 texture { checker texture { Shiny } texture { pigment { rgb <0.2, 0.4, 0.7> } finish { diffuse 0.5 } } scale 0.8 } }
sphere { <-1.2, 1, 0>, 1
  texture { hexagon texture { Shiny } texture { pigment { rgb <0.9, 0.9, 0.6> } }
            texture { pigment { rgb <0.1, 0.6, 0.2> } finish { ambient 0.3 } }
            scale 0.3 rotate x*90 } }
sphere { <1.2, 1, 0>, 1
  pigment { average pigment_map {
    [1 gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } scale 0.7]
    [3 rgb <0.9, 0.9, 0.9>] } } }
sphere { <0, 0.45, -1.6>, 0.45
  pigment { average pigment_map { [checker rgb 1, rgb 0 scale 0.2] [1 rgb <0, 0.5, 1>] } } }
