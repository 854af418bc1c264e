// light_group: each group's light shades only its own objects (the left one also takes the global light, global_lights on); shadows ignore groups (src/scene/object.rs).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 60 right x*image_width/image_height }
light_source { <2, 9, -6> rgb <0.8, 0.8, 0.7> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } finish { ambient 0.1 diffuse 0.7 } }
light_group {
  sphere { <-1.6, 1, 0>, 1 pigment { rgb <1, 0.6, 0.4> } finish { ambient 0.05 diffuse 0.8 phong 0.5 } }
  light_source { <-6, 3, -2> rgb <0.2, 0.5, 1> }
  global_lights on
}
light_group {
  box { <0.6, 0, -0.8>, <2.4, 1.8, 0.8> rotate y*20 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
  light_source { <5, 4, -5> rgb <1, 0.4, 0.2> }
  translate x*0.2
}
