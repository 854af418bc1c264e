// Absorbing media: a box of uniform coloured absorption (exp(-a d) per channel) and a
// sphere whose absorption follows a spherical density, both in front of an emitting
// checker wall. The reference is rendered with --declare MediaIntervals=10
// --declare MediaSamples=10 (POV-Ray's own quadrature is biased at few samples).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 4; #end

camera { location <0, 0, -6> look_at <0, 0, 0> right x*image_width/image_height angle 50 }

plane { -z, -3
  pigment { checker color rgb <1, 0.9, 0.7> color rgb <0.3, 0.5, 0.9> scale 0.5 }
  finish { ambient 1 diffuse 0 } }
box { <-2.4, -1.2, -1>, <-0.4, 1.2, 1> hollow
  pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { absorption <0.2, 0.6, 1.2>
    method 2 intervals MediaIntervals samples MediaSamples } } }
sphere { 0, 1.2 hollow
  pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { absorption 2.5
    method 2 intervals MediaIntervals samples MediaSamples
    density { spherical color_map { [0 rgb 0] [0.6 rgb <1, 0.7, 0.4>] [1 rgb 1] } } } }
  translate <1.4, 0, 0> }
