// square and triangular: four and six entries in the x-z plane; triangles on the floor
// (five colours and POV-Ray's default for the sixth), squares of pigments on a sphere and
// of textures (one with its own finish) turned onto a box, both with POV-Ray's defaults
// elsewhere
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0
  pigment { triangular rgb 0.9, rgb <0.2, 0.3, 0.6>, rgb <0.7, 0.2, 0.1>, rgb 0.4,
    rgb <0.8, 0.7, 0.3> scale 0.6 rotate y*10 }
  finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1
  pigment { square pigment { gradient y } pigment { rgb 0.2 } pigment { rgb <0.3, 0.8, 0.4> }
    scale 0.3 rotate x*70 }
  finish { ambient 0.15 diffuse 0.7 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8>
  texture { square
    texture { pigment { rgb <1, 0.8, 0.2> } finish { specular 0.6 } }
    texture { pigment { rgb <0.1, 0.5, 0.1> } }
    texture { pigment { rgb <0.3, 0.1, 0.5> } }
    texture { pigment { rgb 0.8 } }
    scale 0.4 rotate <30, 0, 60> }
  rotate y*25 translate <1.5, 0, 0.3> }
sphere { <0.2, 0.35, -1.5>, 0.35 pigment { triangular scale 0.1 } finish { ambient 0.3 diffuse 0.6 } }
