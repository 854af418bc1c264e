// bump_map's map types: heights wrapped round a sphere (map_type 1), a cylinder
// (map_type 2) and a torus (map_type 5), each as an image_map of the same type would place
// its colours, lit from two sides so tilts in both directions show
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.2, -7>
  look_at <0, 1, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 2, -3> color rgb 0.4 }

plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.2 diffuse 0.7 } }
sphere { 0, 1
  pigment { rgb <0.9, 0.6, 0.3> }
  normal { bump_map { png "images/hf_hills8.png" map_type 1 interpolate 2 bump_size 60 } }
  finish { ambient 0.15 diffuse 0.7 specular 0.3 }
  rotate y*30 translate <-2, 1.1, 0.5> }
cylinder { <0, 0, 0>, <0, 1, 0>, 1
  pigment { rgb <0.3, 0.5, 0.9> }
  normal { bump_map { png "images/hf_ridges16.png" map_type 2 bump_size 40 } }
  finish { ambient 0.15 diffuse 0.7 specular 0.4 }
  scale <0.8, 2, 0.8> rotate y*-20 translate <0.3, 0, 0.8> }
torus { 1, 0.35
  pigment { rgb <0.5, 0.8, 0.4> }
  normal { bump_map { png "images/hf_hills8.png" map_type 5 interpolate 2 bump_size 60 } }
  finish { ambient 0.15 diffuse 0.7 specular 0.3 }
  rotate x*-60 translate <2.2, 1.2, 0> }
