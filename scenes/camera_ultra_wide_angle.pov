// The ultra_wide_angle camera: ultra_wide_angle at 220 degrees (src/render/camera.rs).
#version 3.7;
camera { ultra_wide_angle angle 220 location <0, 0.2, 0> look_at <0, 0.2, 1> right x*image_width/image_height }
#include "data/camera_ring.inc"
