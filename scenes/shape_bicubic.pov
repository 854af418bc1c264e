// Bicubic patches: a dome at 2^3 x 2^3 sub-patches, a twisted sheet at 2^2 x 2^1 (its
// facets show in the silhouette), one with uv_vectors under a uv_mapping checker, and a
// closed pillow of two patches (type 0 and 1) cut by a box in an intersection, and a saddle
// cut only where it is not flat within `flatness` (measured after its scale); transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.9, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }
#declare F = finish { phong 0.4 }
plane { y, 0 pigment { color rgb <0.55, 0.6, 0.55> } }
#macro Dome(H)
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>,
  <0, 0, 1>, <1, H, 1>, <2, H, 1>, <3, 0, 1>,
  <0, 0, 2>, <1, H, 2>, <2, H, 2>, <3, 0, 2>,
  <0, 0, 3>, <1, 0, 3>, <2, 0, 3>, <3, 0, 3>
#end
bicubic_patch {
  type 1 flatness 0 u_steps 3 v_steps 3
  Dome(2.2)
  pigment { color rgb <0.85, 0.45, 0.25> } finish { F }
  translate <-1.5, 0, -1.5> scale 0.8 rotate <0, 20, 0> translate <-2.6, 0, 1.5>
}
bicubic_patch {
  type 0 flatness 0 u_steps 2 v_steps 1
  <0, 0, 0>, <1, 0.5, 0>, <2, -0.5, 0>, <3, 0, 0>,
  <0, 1, 1>, <1, 1.5, 1>, <2, 0.5, 1>, <3, 1, 1>,
  <0, 2, 1>, <1, 2.5, 1>, <2, 1.5, 1.5>, <3, 2, 1>,
  <0, 2, 0>, <1, 3, 0>, <2, 2, 0>, <3, 2.5, 0>
  pigment { color rgb <0.3, 0.5, 0.9> } finish { F }
  translate <-1.5, 0, 0> scale 0.7 rotate <0, -60, 0> translate <2.6, 0.2, 1.5>
}
bicubic_patch {
  type 1 flatness 0 u_steps 3 v_steps 2
  uv_vectors <0, 0>, <2, 0>, <2, 2>, <0, 2>
  <0, 0, 0>, <1, 0.6, 0>, <2, 0.6, 0>, <3, 0, 0>,
  <0, 0.8, 1>, <1, 1.4, 1>, <2, 1.4, 1>, <3, 0.8, 1>,
  <0, 1.6, 2>, <1, 2.2, 2>, <2, 2.2, 2>, <3, 1.6, 2>,
  <0, 2.2, 3>, <1, 2.8, 3>, <2, 2.8, 3>, <3, 2.2, 3>
  texture { uv_mapping pigment { checker color rgb 1, color rgb 0.15 scale 0.5 } finish { F } }
  rotate <-60, 0, 0> scale 0.6 translate <-0.9, 0.3, 1.8>
}
intersection {
  union {
    bicubic_patch { type 0 flatness 0 u_steps 3 v_steps 3 Dome(1.6) }
    bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3 Dome(-1.6) }
  }
  box { <-1, -2, -1>, <2.2, 2, 2.2> }
  pigment { color rgb <0.3, 0.8, 0.5> } finish { F }
  translate <-1.5, 0, -1.5> scale 0.7 rotate <-25, 30, 0> translate <0.3, 1.3, -1.8>
}
difference {
  box { <-0.8, 0, -0.6>, <0.8, 1.2, 0.6> }
  bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3 Dome(1.5) translate <-1.5, 0.2, -1.5> scale 0.5 }
  pigment { color rgb <0.9, 0.8, 0.2> } finish { F }
  rotate <0, 25, 0> translate <2.8, 0, -1.8>
}
bicubic_patch {
  type 1 flatness 0.15 u_steps 6 v_steps 6
  <0, 1, 0>, <1, 0, 0>, <2, 0, 0>, <3, 1, 0>,
  <0, 0.5, 1>, <1, 0.5, 1>, <2, 0.5, 1>, <3, 0.5, 1>,
  <0, 0.5, 2>, <1, 0.5, 2>, <2, 0.5, 2>, <3, 0.5, 2>,
  <0, 0, 3>, <1, 1, 3>, <2, 1, 3>, <3, 0, 3>
  pigment { checker color rgb <0.9, 0.85, 0.3>, color rgb <0.5, 0.2, 0.6> scale 0.35 }
  finish { phong 0.8 phong_size 40 }
  translate <-1.5, 0, -1.5> scale <0.6, 0.9, 0.5> rotate <0, -25, 0> translate <2.7, 0.1, -2.2>
}
