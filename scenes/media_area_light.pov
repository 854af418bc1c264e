// A slab of scattering media lit by an area light, with an opaque ball between: the ball's
// shadow in the media and on the floor below is soft, and the floor is dimmed by the
// media the light crosses. The reference is rendered with --declare MediaIntervals=10
// --declare MediaSamples=10.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 4; #end

camera { location <0, 2.5, -7> look_at <0, 0.2, 0> right x*image_width/image_height angle 50 }
light_source { <0, 6, 1> color rgb 1.2 area_light <3, 0, 0>, <0, 0, 3>, 5, 5 }

plane { y, -1 pigment { color rgb 0.7 } finish { ambient 0.05 } }
sphere { <0.3, 2.6, 0.8>, 0.5 pigment { color rgb 0.2 } }
box { <-3, -0.5, -1>, <3, 1.5, 3> hollow
  pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { 1, 0.06 }
    method 2 intervals MediaIntervals samples MediaSamples } } }
