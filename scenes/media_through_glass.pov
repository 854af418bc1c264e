// Media seen through refracting glass: a solid glass lens in front of an emitting,
// absorbing column, and a hollow glass ball (ior 1.3) holding scattering media lit by a
// spotlight. The reference is rendered with --declare MediaIntervals=10
// --declare MediaSamples=10.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 4; #end

camera { location <0, 1, -7> look_at <0, 0.5, 0> right x*image_width/image_height angle 50 }
light_source { <4, 7, -3> color rgb 0.8 }
light_source { <1.6, 5, 0> color rgb 2 spotlight point_at <1.6, 0, 0> radius 8 falloff 14 }

plane { y, -1 pigment { checker color rgb 0.8 color rgb 0.25 } }
cylinder { <-1.6, -1, 1.5>, <-1.6, 2.5, 1.5>, 0.7 hollow
  pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission <1, 0.5, 0.2> absorption 0.6
    method 2 intervals MediaIntervals samples MediaSamples } } }
sphere { <-1.6, 0.5, -1>, 1
  pigment { color rgbf <0.95, 1, 0.95, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.5 }
  interior { ior 1.5 } }
sphere { <1.6, 0.4, 0>, 1.1 hollow
  pigment { color rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 reflection 0.05 }
  interior { ior 1.3 media { scattering { 1, <0.15, 0.12, 0.08> }
    method 2 intervals MediaIntervals samples MediaSamples } } }
