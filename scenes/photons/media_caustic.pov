// Photons in media: a glass sphere focuses a spotlight into a cone of light inside a box
// of thin scattering media, in the sphere's shadow (which POV-Ray makes opaque for a
// refracting target). No shadow ray finds that light: it comes only from photons in the
// media (`photons { media }` in global_settings). POV-Ray stores points along the
// photons' paths and gathers them around each media sample; penumbra keeps each path
// through the media whole and gathers its length within a radius that shrinks from sample
// to sample (docs/differences.md, "Photons"). Photon_Count and Photon_Gather set POV-Ray's
// map (POV-Ray takes minutes here at 10^6 photons with the converged quadrature below).
#version 3.7;
#ifndef (Photon_Count) #declare Photon_Count = 1000000; #end
#ifndef (Photon_Gather) #declare Photon_Gather = 20; #end
#ifndef (Media_Converged) #declare Media_Converged = 0; #end
global_settings {
  assumed_gamma 1.0 max_trace_level 8
  photons { count Photon_Count gather Photon_Gather, 5 * Photon_Gather media 100 }
}
camera { location <0, 2, -7> look_at <0, 1.4, 0> right x*4/3 angle 45 }
light_source { <0, 8, 0> color rgb 1.5 spotlight point_at <0, 0, 0> radius 12 falloff 14 }
// The media's container lets photons through (`pass_through`): without it a photon would
// meet the box before the target and be lost, as in POV-Ray.
box { <-2.5, 0.001, -2>, <2.5, 4.5, 2> hollow
  pigment { rgbt 1 }
  photons { pass_through }
  // To compare, POV-Ray's quadrature must converge (its default overshoots: docs/
  // differences.md, "Media: the integral"): Media_Converged=1 asks for `method 2
  // intervals 10 samples 10` (`penumbra reference --converged-media` adds the same),
  // which penumbra would take as 100 points per ray, not needed for its estimate.
  interior { media { scattering { 1, 0.12 }
    #if (Media_Converged) method 2 intervals 10 samples 10 #end } }
}
plane { y, 0 pigment { rgb 0.6 } finish { ambient 0 diffuse 0.8 } }
sphere { <0, 3, 0>, 0.8
  pigment { rgbf <1, 0.97, 0.9, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on reflection off }
}
