// quilted: as a pigment (default controls 1, 1 and 0, 0.5), as a normal (its own
// perturbation), in a texture_map (entries with one finish: texture maps blending different
// ambients do not match POV-Ray yet, whatever the pattern) and through pigment_pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0
  pigment { quilted control0 0 control1 0.5 color_map { [0 rgb <0.1,0.1,0.3>] [0.6 rgb <0.9,0.8,0.6>] } scale 0.7 }
  finish { ambient 0.2 diffuse 0.7 }
}
sphere { <-1.4, 1, 0>, 1
  pigment { rgb <0.9,0.5,0.3> }
  normal { quilted 0.8 scale 0.3 }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 }
}
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> rotate y*25 translate <1.4, 0, 0.2>
  texture {
    quilted
    texture_map {
      [0.2 pigment { rgb <0.2,0.5,0.2> } finish { ambient 0.2 diffuse 0.6 }]
      [0.5 pigment { rgb <1,1,0.9> } finish { ambient 0.2 diffuse 0.6 }]
    }
    scale 0.35
  }
}
sphere { <0.1, 0.45, -1.6>, 0.45
  pigment { rgb 0.8 }
  normal { pigment_pattern { quilted control0 0.5 control1 0.5 color_map { [0 rgb 0] [1 rgb 1] } scale 0.2 } 1.5 }
  finish { ambient 0.1 diffuse 0.8 }
}
