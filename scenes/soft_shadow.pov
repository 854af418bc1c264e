// Soft shadows: a sphere and a box over a floor, lit by a 5x5 area light (POV-Ray's
// non-uniform grid weights) and a dim point light.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}

light_source {
  <-3, 6, -2>
  color rgb <1, 0.95, 0.9>
  area_light <2.5, 0, 0>, <0, 0, 2.5>, 5, 5
}
light_source { <4, 5, -5> color rgb 0.25 }

plane { y, 0 pigment { color rgb <0.8, 0.8, 0.75> } finish { ambient 0.1 diffuse 0.8 } }
sphere { <-0.6, 1, 0.3>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 phong_size 30 } }
box { <0.7, 0, -1.2>, <1.7, 0.8, -0.2> pigment { color rgb <0.2, 0.5, 0.9> } }
