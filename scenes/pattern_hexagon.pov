// hexagon: three colours on a floor, on a sphere and rotated onto a box
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { hexagon rgb <0.9,0.9,0.9>, rgb <0.2,0.3,0.6>, rgb <0.7,0.2,0.1> scale 0.5 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1 pigment { hexagon rgb 0.1, rgb 0.6, rgb 1 scale 0.2 rotate x*90 } finish { ambient 0.15 diffuse 0.7 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> rotate y*25 translate <1.5, 0, 0.3> pigment { hexagon pigment { rgb <1,0.8,0.2> } pigment { rgb <0.1,0.5,0.1> } pigment { rgb <0.3,0.1,0.5> } scale 0.25 rotate <30,0,60> } }
