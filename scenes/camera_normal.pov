// Camera normal: a leopard pattern tilts every primary ray, read at the screen point (src/render/camera.rs).
#version 3.7;
camera { location <0, 0.6, -3> look_at <0, 0.3, 4> angle 80 right x*image_width/image_height
  normal { leopard 0.6 scale 0.06 } }
#include "data/camera_ring.inc"
