// Photons: a glass sphere (photons refract) focuses a point light into a caustic on the
// floor, inside the sphere's shadow, which POV-Ray makes opaque for a refracting target;
// a tilted mirror (photons reflect) throws a second, softer patch of the light back onto
// the floor. POV-Ray's photon map is noisy and blurred by its gather radius; penumbra's
// passes shrink their radius, so the two agree only as POV-Ray's count grows (the
// script scripts/photons_convergence.py sets the count with Photon_Count).
#version 3.7;
#ifndef (Photon_Count) #declare Photon_Count = 1000000; #end
#ifndef (Photon_Gather) #declare Photon_Gather = 20; #end
global_settings { assumed_gamma 1.0 max_trace_level 8 photons { count Photon_Count gather Photon_Gather, 5 * Photon_Gather } }
camera { location <0, 5, -6> look_at <0, 0.5, 0.3> right x*4/3 angle 45 }
light_source { <-0.2, 7, 3.5> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 } }
sphere { <-0.6, 1, 0>, 1
  pigment { rgbf <1, 0.95, 0.8, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.25 }
  photons { target refraction on reflection off }
}
box { <-1, 0, -0.05>, <1, 1.6, 0.05>
  pigment { rgb 0 }
  finish { ambient 0 diffuse 0 reflection 0.9 }
  rotate y*-35 rotate x*10 translate <2.1, 0.2, 1.2>
  photons { target reflection on }
}
