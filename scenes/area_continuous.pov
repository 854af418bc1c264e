// A square area light whose grid size is a parameter: POV-Ray with AreaN = 2^k+1 large and
// no jitter converges to the continuous emitter penumbra samples with --area-lights
// continuous. The reference tool overrides AreaN (e.g. --declare AreaN=33).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (AreaN) #declare AreaN = 5; #end

camera {
  location <0, 3.5, -6>
  look_at <0, 0.5, 0>
  right x*image_width/image_height
  angle 45
}
light_source {
  <-1, 4, -1> color rgb 1
  area_light <3, 0, 0>, <0, 0, 3>, AreaN, AreaN
}

plane { y, 0 pigment { color rgb 0.85 } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.3, 0.6, 0.9> } }
box { <1.2, 0, -1>, <1.7, 2, -0.5> pigment { color rgb <0.9, 0.8, 0.3> } }
