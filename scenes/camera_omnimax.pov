// The omnimax camera: a 180-degree dome view, its lower part cut off 45 degrees below the view (src/render/camera.rs).
#version 3.7;
camera { omnimax location <0, 0.2, 0> look_at <0, 0.2, 1> right x*image_width/image_height }
#include "data/camera_ring.inc"
