// planar and marble with a colour map: marble's default triangle wave, planar's falloff;
// wood without a map shows POV-Ray's default brown one
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 5, -8> color rgb 1 }

plane { z, 1 pigment { planar color_map { [0 rgb <0.1,0.1,0.2>] [1 rgb <1,0.9,0.7>] } scale 1.5 } finish { ambient 0.3 diffuse 0.6 } }
sphere { <-1.1, 0, 0>, 1 pigment { marble color_map { [0 rgb <0.2,0.1,0.05>] [0.7 rgb <0.9,0.8,0.7>] [1 rgb 1] } scale 0.6 rotate z*30 } }
sphere { <1.1, 0, 0>, 1 pigment { wood frequency 2 color_map { [0 rgb <0.4,0.2,0.05>] [1 rgb <0.9,0.6,0.3>] } scale 0.5 rotate x*80 } }
sphere { <0, -0.95, -1.2>, 0.55 pigment { wood scale 0.25 rotate <60, 20, 0> } }
