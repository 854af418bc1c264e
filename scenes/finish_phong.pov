// Finish phong and phong_size: highlights of strength 0.3 to 1 and sizes 5 to 200, and
// `phong albedo` (scaled by (phong_size+1)/2), on dark spheres under two lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 6, -5> color rgb 1 }
light_source { <5, 2, -3> color rgb <0.4, 0.5, 0.7> }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.3, 0.3, 0.3> } finish { phong 0.5 phong_size 10 } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <0.2, 0.1, 0.1> } finish { phong 0.3 phong_size 5 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <0.1, 0.2, 0.1> } finish { phong 1 } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb <0.1, 0.1, 0.2> } finish { phong 0.8 phong_size 200 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.2, 0.2, 0.1> } finish { phong albedo 0.05 phong_size 20 } }
