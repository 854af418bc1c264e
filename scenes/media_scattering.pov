// Scattering media, every phase function: five spheres (isotropic, Mie haze, Mie murky,
// Rayleigh, Henyey-Greenstein with eccentricity 0.6) lit by a light behind them and one in
// front, so forward and back scattering both show; the light also reaches the floor
// through them (media shadows). The reference is rendered with --declare
// MediaIntervals=10 --declare MediaSamples=10.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 4; #end

camera { location <0, 1.5, -8> look_at <0, 0.3, 0> right x*image_width/image_height angle 50 }
light_source { <2, 5, 12> color rgb <1, 0.95, 0.85> }
light_source { <-6, 3, -6> color rgb <0.2, 0.3, 0.5> }

plane { y, -1 pigment { color rgb 0.5 } }
#macro Cloud(Type, X)
  sphere { 0, 0.8 hollow
    pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
    interior { media {
      scattering { Type, <0.12, 0.15, 0.2> #if (Type = 5) eccentricity 0.6 #end extinction 0.8 }
      method 2 intervals MediaIntervals samples MediaSamples } }
    translate <X, 0, 0> }
#end
Cloud(1, -3.6)
Cloud(2, -1.8)
Cloud(3, 0)
Cloud(4, 1.8)
Cloud(5, 3.6)
