// Finish `diffuse albedo k`: the diffuse value becomes k*(brilliance+1)/2, with brilliance
// given before or after it, next to a plain diffuse sphere of the same number.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-5, 5, -4> color rgb 1 }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } finish { diffuse albedo 0.5 } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <0.4, 0.7, 0.9> } finish { ambient 0.05 diffuse 0.6 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <0.4, 0.7, 0.9> } finish { ambient 0.05 diffuse albedo 0.6 } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb <0.4, 0.7, 0.9> } finish { ambient 0.05 diffuse albedo 0.4 brilliance 2 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.4, 0.7, 0.9> } finish { ambient 0.05 brilliance 0.5 diffuse albedo 0.9 } }
