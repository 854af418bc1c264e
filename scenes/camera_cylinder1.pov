// The cylinder1 camera: a vertical cylinder from a fixed point, angle 100 (src/render/camera.rs).
#version 3.7;
camera { cylinder 1 angle 100 location <0, 0.2, 0> look_at <0, 0.2, 1> right x*image_width/image_height }
#include "data/camera_ring.inc"
