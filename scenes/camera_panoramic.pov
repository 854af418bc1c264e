// The panoramic camera: panoramic (angle ignored; right's length stretches it) (src/render/camera.rs).
#version 3.7;
camera { panoramic location <0, 0.2, 0> look_at <0, 0.2, 1> right x*image_width/image_height }
#include "data/camera_ring.inc"
