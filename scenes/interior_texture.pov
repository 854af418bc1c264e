// interior_texture: a cut-open sphere and an open cylinder show their inner sides in the interior texture (src/render/prepared.rs).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -6> look_at <0, 0.6, 0> angle 55 right x*image_width/image_height }
light_source { <-4, 8, -5> rgb 1 }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.55 } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-1.3, 1, 0>, 1
  texture { pigment { rgb <0.2, 0.4, 0.9> } finish { ambient 0.1 diffuse 0.7 phong 0.4 } }
  interior_texture { pigment { gradient y color_map { [0 rgb <1, 0.5, 0.1>] [1 rgb <1, 0.9, 0.3>] } } finish { ambient 0.2 diffuse 0.6 } }
  clipped_by { plane { <0, 1, -0.6>, 0.25 translate <-1.3, 1, 0> } }
}
cylinder { <1.4, 0, 0>, <1.4, 1.6, 0>, 0.8 open
  pigment { rgb <0.3, 0.8, 0.4> } finish { ambient 0.1 diffuse 0.7 }
  interior_texture { pigment { checker rgb <0.9, 0.2, 0.2> rgb <1, 1, 1> scale 0.25 } finish { ambient 0.1 diffuse 0.7 } }
}
