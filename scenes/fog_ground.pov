// Ground fog: dense below fog_offset, thinning as 1 / (1 + u^2) above it (u the height over
// fog_alt), integrated along each ray; a second ground fog with a tilted `up`; rays that
// leave upwards see the sky through what fog lies above them.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.2, -8>
  look_at <0, 1.2, 0>
  right x*image_width/image_height
  angle 65
}
light_source { <6, 10, -8> color rgb 1 }
background { color rgb <0.25, 0.45, 0.85> }

fog { fog_type 2 distance 6 fog_offset 0.4 fog_alt 1.2 color rgb <0.9, 0.9, 0.95> }
fog { fog_type 2 distance 20 fog_offset -1 fog_alt 2 up <0.3, 1, 0> color rgbf <0.9, 0.6, 0.3, 0.5> }

plane { y, 0 pigment { checker color rgb 0.8 color rgb <0.1, 0.25, 0.1> scale 2 } }
sphere { <-2.5, 0.8, 2>, 0.8 pigment { color rgb <0.8, 0.2, 0.2> } }
sphere { <2, 2.5, 6>, 2.5 pigment { color rgb <0.2, 0.5, 0.9> } }
cylinder { <0, 0, 12>, <0, 6, 12>, 0.6 pigment { color rgb 0.9 } }
