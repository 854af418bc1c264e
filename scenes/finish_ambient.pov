// Finish ambient: grey, coloured and zero ambient on spheres lit by one light, two with
// diffuse 0 so only the ambient term shows, under a tinted global ambient_light.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <0.8, 1, 1.3> }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 6, -5> color rgb 1 }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } finish { ambient 0.3 diffuse 0.4 } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.5, 0.2> } finish { ambient 0.6 diffuse 0 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <0.3, 0.8, 0.9> } finish { ambient rgb <0.2, 0.6, 0.9> diffuse 0 } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb <0.8, 0.8, 0.3> } finish { ambient 0 diffuse 0.7 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.5, 0.4, 0.9> } finish { ambient 0.4 diffuse 0.5 } }
