// bump_map's options and a density_file normal: `interpolate 2` blends the heights between
// pixel centres (a tilted box face, the image enlarged so each pixel spans many), `use_index`
// takes POV-Ray's palette bumpmap_.png's indices as heights (a floor), and a normal's
// density_file takes `interpolate 1` after its amount (POV-Ray's spiral.df3, as
// textures/patterns/densfile.pov writes it). The camera sees no top face of the boxes: where
// the surface normal is the bump map's own y axis POV-Ray still tilts it, by a rule not yet
// measured (docs/differences.md)
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2, -7>
  look_at <0, 1.2, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 2, -3> color rgb 0.4 }

plane { y, 0 pigment { rgb 0.8 }
  normal { bump_map { png "bumpmap_.png" use_index bump_size 0.02 } rotate x*90 scale 6 }
  finish { ambient 0.2 diffuse 0.7 } }
box { <-2.7, 0.25, -0.1>, <-0.3, 2.15, 0.1>
  pigment { rgb <0.9, 0.6, 0.3> }
  normal { bump_map { png "images/hf_hills8.png" interpolate 2 once bump_size 30 }
    scale <2.6, 2, 1> translate <-2.8, 0.2, 0> }
  finish { ambient 0.15 diffuse 0.7 specular 0.3 }
  rotate y*20
}
box { <0.3, 0.2, -0.1>, <2.5, 2.4, 0.1>
  pigment { rgb <0.3, 0.5, 0.9> }
  normal { density_file df3 "spiral.df3", 2.6 interpolate 1
    translate <-0.5, -0.5, -0.5> scale <2.2, 2.2, 0.2> translate <1.4, 1.3, 0> }
  finish { ambient 0.15 diffuse 0.7 specular 0.4 }
  rotate y*-15
}
