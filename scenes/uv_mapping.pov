// uv_mapping: an image wrapped by the surface's own (u, v) on a sphere (u around y from +x,
// v by latitude) and a box (the six faces unfolded into a cross), a uv checker on a torus
// and, through the texture, on a cylinder (no uv of its own: povray falls back to world x, y)
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3.2, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 52
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { checker rgb 0.6, rgb 0.3 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.6, 1, 0.2>, 1
  pigment { uv_mapping image_map { png "images/test_card.png" interpolate 2 } }
  finish { ambient 0.15 diffuse 0.7 }
  rotate y*-30 translate <0, 0, 0>
}
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7>
  pigment { uv_mapping image_map { png "images/test_card.png" } }
  finish { ambient 0.15 diffuse 0.7 }
  rotate y*35 translate <1.5, 0, 0.4>
}
torus { 0.55, 0.22
  texture { uv_mapping pigment { checker rgb <0.9, 0.2, 0.1>, rgb <0.95, 0.9, 0.4> scale <1/12, 1/4, 1> } finish { ambient 0.2 diffuse 0.7 } }
  rotate x*-60 translate <0, 0.75, -1.4>
}
cylinder { <0, 0, 2.2>, <0, 2.2, 2.2>, 0.6
  pigment { uv_mapping checker rgb 0.1, rgb 0.8 scale 0.25 }
  finish { ambient 0.2 diffuse 0.7 }
}
