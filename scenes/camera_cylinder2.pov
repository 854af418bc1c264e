// The cylinder2 camera: a horizontal cylinder from a fixed point (src/render/camera.rs).
#version 3.7;
camera { cylinder 2 angle 90 location <0, 0.2, 0> look_at <0, 0.2, 1> right x*image_width/image_height }
#include "data/camera_ring.inc"
