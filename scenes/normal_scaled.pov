// Normals under scales that are not uniform: POV-Ray perturbs the normal in pattern space
// and brings it back as a normal, so squeezing a pattern along the surface steepens its
// bumps and squeezing it across the surface flattens them (ripples on the floor squeezed in
// x, leopard on a box squeezed in z and turned, wrinkles-free gradient ramps on a sphere)
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.8, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.4 }

plane { y, 0 pigment { rgb 0.8 }
  normal { ripples 0.4 scale <0.3, 1, 1> }
  finish { ambient 0.2 diffuse 0.7 } }
box { <-2.8, 0.2, -0.3>, <-0.4, 2, 0.3>
  pigment { rgb <0.9, 0.6, 0.3> }
  normal { leopard 0.8 scale 0.15 scale <1, 0.5, 0.2> rotate <20, 30, 10> }
  finish { ambient 0.15 diffuse 0.7 specular 0.3 }
  rotate y*15
}
sphere { <1.3, 1, 0.3>, 1
  pigment { rgb <0.3, 0.5, 0.9> }
  normal { gradient x 0.5 scale <0.4, 1, 1> rotate z*30 }
  finish { ambient 0.15 diffuse 0.7 specular 0.4 }
}
