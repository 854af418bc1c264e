// Normals as values and as the entries of list patterns: a declared normal used as is and
// modified, a checker of two normals, a hexagon of three, a brick of two, and a declared
// normal holding a normal_map (transformed after its map, as the entries then are too).
// Only patterns without noise, so the image is POV-Ray's pixel for pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.2, -6> look_at <0, 0.6, 0> right x*image_width/image_height angle 52 }
light_source { <-3, 7, -4> color rgb 1 }

#declare Rings = normal { ripples 0.8 frequency 3 scale 0.5 }
#declare Bands = normal { gradient y 1
  normal_map { [0.3 waves 0.6 frequency 3] [0.7 ripples 0.8 frequency 4] [1 leopard 0.5 scale 0.1] } }
#declare Finish = finish { phong 0.6 phong_size 40 specular 0.2 }

plane { y, 0
  pigment { rgb <0.75, 0.72, 0.65> } finish { Finish }
  normal { checker normal { Rings } normal { waves 0.6 frequency 2 scale 0.4 } scale 1.2 } }
sphere { <-1.6, 0.9, 0>, 0.9
  pigment { rgb <0.8, 0.3, 0.2> } finish { Finish }
  normal { hexagon normal { Rings } normal { leopard 0.7 scale 0.1 } normal { onion 0.5 scale 0.3 }
           scale 0.35 rotate x*90 } }
sphere { <0.4, 0.9, 0.4>, 0.9
  pigment { rgb <0.2, 0.5, 0.8> } finish { Finish } normal { Bands scale 0.5 } }
box { <1.6, 0, -1.4>, <2.8, 1.2, -0.2>
  pigment { rgb <0.9, 0.85, 0.4> } finish { Finish }
  normal { brick normal { Rings scale 0.5 } normal { radial 0.6 frequency 12 } brick_size <0.5, 0.25, 0.5> mortar 0.05 } }
sphere { <-0.3, 0.45, -1.6>, 0.45
  pigment { rgb <0.6, 0.8, 0.5> } finish { Finish } normal { Rings bump_size 1.5 } }
