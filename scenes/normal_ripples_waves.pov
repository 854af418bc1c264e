// ripples and waves as normals and as patterns: POV-Ray's ten wave sources (measured),
// frequency and phase inside the waves, a scaled and a rotated copy
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3.2, -6>
  look_at <0, 0.5, 0>
  right x*image_width/image_height
  angle 55
}
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }

plane { y, 0 pigment { rgb <0.7, 0.75, 0.8> } normal { ripples 0.6 frequency 1.5 phase 0.2 scale 0.8 }
  finish { ambient 0.1 diffuse 0.7 phong 0.4 phong_size 30 } }
sphere { <-1.5, 1, 0.5>, 1 pigment { rgb <0.9, 0.5, 0.3> } normal { waves 0.5 scale 0.3 }
  finish { ambient 0.1 diffuse 0.7 } }
sphere { <1.4, 1, 0.3>, 1 pigment { waves frequency 2 color_map { [0 rgb <0.1,0.2,0.6>] [1 rgb <0.9,0.9,0.6>] } scale 0.4 }
  normal { ripples 1 rotate x*40 scale 0.25 } finish { ambient 0.1 diffuse 0.7 } }
box { <-0.5, 0, -0.5>, <0.5, 0.8, 0.5> rotate y*30 translate <0, 0, -1.6>
  pigment { ripples phase 0.3 color_map { [0 rgb 0.2] [1 rgb <1,0.8,0.5>] } scale 0.3 }
  normal { waves 1 frequency 3 } finish { ambient 0.15 diffuse 0.6 } }
