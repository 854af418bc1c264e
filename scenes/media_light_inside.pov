// A light inside a medium: a hollow sphere of scattering and absorbing media holds the
// light, a white box, and a clear ball around a second light. POV-Ray 3.7 attenuates a
// shadow ray by the objects' media only up to the last surface it crosses, so light
// reaches the medium's own points and the box unattenuated, and through the clear ball
// only the stretch inside the ball goes free (docs/differences.md). The reference is
// rendered with --declare MediaIntervals=10 --declare MediaSamples=10.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 4; #end

camera { location <0, 1, -22> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-3, 4, 0> color rgb <1, 0.9, 0.7> }
light_source { <4, -1, 2> color rgb <0.4, 0.6, 1> }
plane { y, -7 pigment { checker color rgb 0.6 color rgb 0.2 scale 2 } }
sphere { 0, 6.5 hollow
  pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { 1, 0.04 } absorption <0.04, 0.06, 0.1>
    method 2 intervals MediaIntervals samples MediaSamples } } }
box { <-3, -4.5, -1>, <2, -3.5, 2> pigment { color rgb 1 } finish { ambient 0 diffuse 0.8 } }
sphere { <4, -1, 2>, 1.2 hollow pigment { color rgbt 1 } finish { ambient 0 diffuse 0 } }
