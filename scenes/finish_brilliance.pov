// Finish diffuse with brilliance: (N.L)^brilliance for brilliance 0.3, 1, 3 and 10, seen
// across the terminator of four spheres lit from the side.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-6, 4, -2> color rgb 1 }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } finish { brilliance 2 } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.6, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 0.3 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.6, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 1 } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.6, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 3 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.6, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 10 } }
