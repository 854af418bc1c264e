// Atmospheric media: a room filled with a scattering haze (a top-level media), a spotlight
// whose beam the haze shows, a ball casting a shadow through the beam, and the beam's
// light dimmed on the way (media_attenuation on). The camera is inside the hollow room.
// The reference is rendered with --declare MediaIntervals=10 --declare MediaSamples=10.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 4; #end

camera { location <3, 3, -9> look_at <0, 2.5, 0> right x*image_width/image_height angle 55 }
media { scattering { 1, 0.04 } absorption 0.01
  method 2 intervals MediaIntervals samples MediaSamples }
light_source { <0, 15, 0> color rgb 0.3 media_interaction off shadowless }
light_source { <-4, 9, -1> color rgb <1, 0.9, 0.7> * 2.5
  spotlight point_at <0, 0, 1> radius 12 falloff 18 tightness 1
  media_attenuation on }
box { <-10, 0, -10>, <10, 10, 10> hollow
  pigment { color rgb 0.8 } finish { ambient 0.1 diffuse 0.6 } }
sphere { <-1.6, 5.2, -0.3>, 0.8 pigment { color rgb <0.8, 0.2, 0.1> } }
