// Focal blur with 37 samples: the whole of POV-Ray's 37-cell lens grid, traced in POV-Ray's order
// under its rule for stopping a pixel's lens samples early (src/render/camera.rs).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1, -5>
  look_at <0, 1, 0>
  right x*image_width/image_height
  angle 40
  aperture 0.4
  blur_samples 37
  focal_point <0, 1, 0>
}
light_source { <-3, 6, -4> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <0, 1, 0>, 0.5 pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.5 } }
sphere { <1.2, 0.5, -2>, 0.3 pigment { color rgb <0.2, 0.3, 1> } }
sphere { <-1.5, 1.5, 4>, 0.6 pigment { color rgb <0.2, 1, 0.3> } }
