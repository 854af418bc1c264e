// Checker patterns: a checkered floor, a scaled and rotated checker on a box, and brilliance
// and specular on a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <1, 4, -6>
  look_at <0, 0.5, 0>
  right x*image_width/image_height
  angle 45
}
light_source { <-3, 8, -4> color rgb 1 }

plane {
  y, 0
  pigment { checker color rgb <0.9, 0.9, 0.9> color rgb <0.15, 0.15, 0.2> }
  finish { diffuse 0.7 }
}
box {
  <-1, 0, -1>, <1, 1.5, 1>
  pigment { checker color rgb <0.9, 0.2, 0.1> color rgb <0.95, 0.8, 0.2> scale 0.5 }
  rotate y*30
  translate <-1.8, 0, 1>
}
sphere {
  <1.5, 1, 0>, 1
  pigment { checker rgb <0.1, 0.4, 0.8> rgb <0.9, 0.9, 0.9> scale 0.4 }
  finish { brilliance 2 specular 0.5 roughness 0.05 }
}
