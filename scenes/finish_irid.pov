// irid: thin-film interference on diffuse, phong and specular light (amount, thickness,
// irid_wavelength), lit from two sides
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength rgb <0.65, 0.5, 0.4> }

camera { location <0, 1.5, -7> look_at <0, 0.4, 0> right x*image_width/image_height angle 45 }
light_source { <-6, 8, -6> color rgb 0.9 }
light_source { <5, 3, -4> color rgb <0.5, 0.6, 0.7> }

plane { y, -1 pigment { checker rgb 0.7, rgb 0.3 } finish { ambient 0.1 diffuse 0.6 irid { 0.4 thickness 0.3 } } }
sphere { <-1.8, 0, 0>, 1 pigment { rgb <0.8, 0.8, 0.9> } finish { ambient 0.05 diffuse 0.8 irid { 0.35 thickness 0.5 } } }
sphere { <0.4, 0.2, 0.5>, 1.2 pigment { rgb <0.3, 0.5, 0.8> } finish { ambient 0 diffuse 0.7 phong 0.8 phong_size 20 irid { 0.6 thickness 0.25 } } }
sphere { <2.2, 0, -0.4>, 0.9 pigment { rgb 0.9 } finish { diffuse 0.6 specular 0.7 roughness 0.02 irid { 1 thickness 1.2 } } }
