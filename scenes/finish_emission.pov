// Finish emission: emission adds the pigment times the emission colour, independently of
// ambient and of the lights (and ambient_light does not scale it); a transmitting sphere
// shows that emission is scaled by the opacity.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 0.5 }

camera {
  location <0, 1.6, -6>
  look_at <0, 0.7, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 6, -5> color rgb 0.8 }
background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } }
sphere { <-2.1, 0.7, 0>, 0.7 pigment { color rgb <0.9, 0.5, 0.2> } finish { ambient 0 diffuse 0 emission 0.9 } }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { color rgb <0.3, 0.8, 0.9> } finish { ambient 0.2 emission rgb <0.6, 0.3, 0.1> } }
sphere { <0.7, 0.7, 0>, 0.7 pigment { color rgb <0.8, 0.8, 0.3> } finish { emission 1.5 diffuse 0.3 } }
sphere { <2.1, 0.7, 0>, 0.7 pigment { color rgb <0.5, 0.4, 0.9> transmit 0.5 } finish { emission 1 diffuse 0 } }
