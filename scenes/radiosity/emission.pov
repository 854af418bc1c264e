// Radiosity, emission lighting: no light source; a closed room is lit only by an emitting
// panel under its ceiling (finish emission), whose light reaches the room only as
// radiosity gathers it, through two diffuse bounces.
#version 3.7;
// POV-Ray's cache quality comes from the declares (Rad_Preset: a rad_def.inc preset;
// scripts/radiosity_convergence.py sets them); penumbra's image does not depend on them.
#ifndef(Rad_Count) #declare Rad_Count = 200; #end
#ifndef(Rad_Error) #declare Rad_Error = 0.3; #end
#ifndef(Rad_Nearest) #declare Rad_Nearest = 7; #end
#ifndef(Rad_Reuse) #declare Rad_Reuse = 0.015; #end
#ifndef(Rad_Pretrace) #declare Rad_Pretrace = 0.01; #end
#ifdef(Rad_Preset) #include "rad_def.inc" #end
global_settings {
  assumed_gamma 1.0
  #ifndef(No_Radiosity)
  radiosity {
    #ifdef(Rad_Preset)
      Rad_Settings(Rad_Preset, off, off)
    #else
      count Rad_Count error_bound Rad_Error nearest_count Rad_Nearest
      minimum_reuse Rad_Reuse pretrace_start 0.08 pretrace_end Rad_Pretrace
      low_error_factor 0.5 adc_bailout 0.001
    #end
    // After the preset, which would set its own: the integral both renderers compute.
    recursion_limit 2
  }
  #end
}
camera { location <0, 1.2, -1.9> look_at <0, 0.7, 0> right x*image_width/image_height angle 70 }
// The room, seen from inside.
box { <-2, 0, -2>, <2, 2.4, 2> pigment { rgb 0.7 } finish { ambient 0 diffuse 0.8 } }
box { <-0.8, 2.3, -0.8>, <0.8, 2.35, 0.8> pigment { rgb <1, 0.9, 0.7> }
  finish { ambient 0 diffuse 0 emission 3 } }
sphere { <-0.5, 0.45, 0.3>, 0.45 pigment { rgb <0.2, 0.4, 0.9> } finish { ambient 0 diffuse 0.8 } }
box { <0.2, 0, -0.2>, <0.9, 0.9, 0.5> rotate y*25 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 } }
