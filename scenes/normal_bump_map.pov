// bump_map: heights from an image tilt the normal. POV-Ray's own bumpmap_.png (a palette
// image, found through the include path) by brightness on a box face and turned onto the
// floor; this project's grey hills image on a sphere, once and scaled
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.8, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { rgb 0.8 }
  normal { bump_map { png "bumpmap_.png" bump_size 1 } rotate x*90 scale 4 }
  finish { ambient 0.2 diffuse 0.7 } }
box { <-2.8, 0.2, -0.1>, <-0.4, 2, 0.1>
  pigment { rgb <0.9, 0.6, 0.3> }
  normal { bump_map { png "bumpmap_.png" bump_size 2 } scale <2.4, 1.8, 1> translate <-2.8, 0.2, 0> }
  finish { ambient 0.15 diffuse 0.7 specular 0.3 }
}
sphere { <1.3, 1, 0.3>, 1
  pigment { rgb <0.3, 0.5, 0.9> }
  normal { bump_map { png "images/hf_hills8.png" once bump_size 4 } scale 1.6 translate <0.5, 0.2, 0> }
  finish { ambient 0.15 diffuse 0.7 specular 0.4 }
}
