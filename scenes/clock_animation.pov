// Animation: a ball rolls across a checkered floor and a box turns as `clock` goes from 0 to
// 1 (+KFI1 +KFF5 renders it in five frames; the frames differ only through `clock`).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.5, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}

light_source { <-3, 6, -4> color rgb 1 }
light_source { <4, 4, -5> color rgb 0.3 shadowless }

plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.3 } finish { ambient 0.1 diffuse 0.8 } }
sphere {
  <-2 + 4*clock, 0.6, 0>, 0.6
  pigment { color rgb <0.9, 0.3, 0.2> }
  finish { phong 0.5 phong_size 40 }
}
box {
  <-0.5, 0, -0.5>, <0.5, 1, 0.5>
  rotate y*90*clock
  translate <0.5, 0, 1.5>
  pigment { color rgb <0.2, 0.5, 0.9> }
}
