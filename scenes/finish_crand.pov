// Finish crand: per-sample random darkening; only its converged mean is compared, on a
// bright, a dark and a lit plane surface with crand 0.1 to 0.5.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 6, -5> color rgb 1 }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } finish { crand 0.2 } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.8, 0.7> } finish { crand 0.1 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.8, 0.7> } finish { crand 0.5 } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb <0.1, 0.2, 0.3> } finish { crand 0.3 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.4, 0.2> } finish { ambient 0.5 crand 0.3 } }
