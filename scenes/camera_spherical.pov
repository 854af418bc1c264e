// The spherical camera: longitude and latitude, angle 300 x 140 (src/render/camera.rs).
#version 3.7;
camera { spherical angle 300, 140 location <0, 0.2, 0> look_at <0, 0.2, 1> right x*image_width/image_height }
#include "data/camera_ring.inc"
