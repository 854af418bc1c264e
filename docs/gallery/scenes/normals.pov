// normals: bumps, dents, wrinkles, gradient and hexagon as normals (shows once the integrator shades with perturbed_normal)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -9> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-5, 5, -10> color rgb 1 }
#declare F = finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 60 }
sphere { <-2.4, 1.2, 0>, 1.1 pigment { rgb <0.9,0.8,0.6> } normal { bumps 0.6 scale 0.2 } finish { F } }
sphere { <0, 1.2, 0>, 1.1 pigment { rgb <0.6,0.8,0.9> } normal { dents 1.5 scale 0.3 } finish { F } }
sphere { <2.4, 1.2, 0>, 1.1 pigment { rgb <0.9,0.6,0.6> } normal { wrinkles 0.8 scale 0.4 } finish { F } }
sphere { <-1.2, -1.2, 0>, 1.1 pigment { rgb 0.9 } normal { gradient x, 4 scale 0.3 } finish { F } }
sphere { <1.2, -1.2, 0>, 1.1 pigment { rgb 0.9 } normal { hexagon 1.6 scale 0.2 rotate x*90 } finish { F } }
