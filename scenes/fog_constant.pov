// Constant fog: two fogs at once (their factors multiply, their colours add), one filtered
// (it tints what is seen through it) with a transmit floor (the background keeps 25% of
// itself); fog on mirror rays, inside a hollow glass sphere but not inside a solid one.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 1.6, -6>
  look_at <0, 1, 2>
  right x*image_width/image_height
  angle 60
}
light_source { <-5, 8, -6> color rgb 1 }
background { color rgb <0.2, 0.35, 0.7> }

fog { distance 20 color rgbft <0.85, 0.8, 0.7, 0.4, 0.25> }
fog { distance 40 color rgb <0.3, 0.1, 0.05> }

plane { y, 0 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.2> scale 2 } }
// The far wall faces the camera, which is outside its solid (z > 18).
plane { -z, -18 pigment { color rgb <0.9, 0.5, 0.2> } }
sphere { <-2.6, 1, 2>, 1 pigment { color rgb <0.9, 0.2, 0.2> } }
sphere { <2.6, 1.3, 7>, 1.3 pigment { color rgb 0.95 } finish { ambient 0 diffuse 0.2 reflection 0.7 } }
sphere { <-0.9, 0.9, -1.5>, 0.9
  pigment { color rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 }
  interior { ior 1.0 } }
sphere { <1.0, 0.9, -1.5>, 0.9 hollow
  pigment { color rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 }
  interior { ior 1.0 } }
