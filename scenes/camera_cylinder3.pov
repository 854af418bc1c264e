// The cylinder3 camera: a vertical cylinder whose viewpoint moves along its axis (src/render/camera.rs).
#version 3.7;
camera { cylinder 3 angle 160 location <0, 0.2, 0> look_at <0, 0.2, 1> right x*image_width/image_height }
#include "data/camera_ring.inc"
