// tiles: a checker of two textures (each with its own finish, the second layered), the
// form advanced/chess2.pov and wineglass.pov use
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -7> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-5, 9, -6> color rgb 1 }

plane { y, 0
  texture { tiles {
      texture { pigment { gradient x color_map { [0 rgb <0.9,0.8,0.6>] [1 rgb <0.6,0.4,0.2>] } scale 0.5 }
                finish { ambient 0.1 diffuse 0.7 phong 0.6 } }
      tile2
      texture { pigment { rgb <0.1,0.15,0.3> } finish { ambient 0.05 diffuse 0.5 specular 0.6 roughness 0.02 } }
    } scale 1.5 rotate y*20 } }
sphere { <0, 1, 0>, 1
  texture { tiles { texture { pigment { rgb <0.8,0.2,0.1> } } tile2 texture { pigment { rgb 0.9 } finish { phong 0.8 } } } scale 0.5 } }
