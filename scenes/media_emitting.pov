// Emitting media: a sphere glowing with a spherical density whose colour map tints it, and
// a box that both emits and absorbs (e (1 - exp(-a d)) / a), over a dark floor. The
// reference is rendered with --declare MediaIntervals=10 --declare MediaSamples=10.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 4; #end

camera { location <0, 1, -7> look_at <0, 0.6, 0> right x*image_width/image_height angle 50 }
light_source { <3, 6, -4> color rgb 0.6 }

plane { y, -1 pigment { color rgb 0.3 } }
sphere { 0, 1 hollow
  pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission 1.5
    method 2 intervals MediaIntervals samples MediaSamples
    density { spherical ramp_wave
      color_map { [0 rgb 0] [0.3 rgb <1, 0.3, 0.1>] [1 rgb <1, 1, 0.2>] } } } }
  scale 1.4 translate <-1.4, 0.6, 0> }
box { <-0.8, -0.8, -0.8>, <0.8, 0.8, 0.8> hollow
  pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission <0.2, 0.6, 1.0> absorption <0.8, 0.5, 0.2>
    method 2 intervals MediaIntervals samples MediaSamples } }
  rotate <20, 35, 0> translate <1.6, 0.4, 0.5> }
