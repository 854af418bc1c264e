// The fisheye camera: a fisheye of 200 degrees (black outside its circle) (src/render/camera.rs).
#version 3.7;
camera { fisheye angle 200 location <0, 0.2, 0> look_at <0, 0.2, 1> right x*image_width/image_height }
#include "data/camera_ring.inc"
