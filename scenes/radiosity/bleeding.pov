// Radiosity, colour bleeding and sky light: an orange wall and a white sphere on a white
// floor under a blue sky (the background, which radiosity gathers as light), lit by a
// low sun; the sphere's shaded side turns orange, the floor's shadow blue.
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
camera { location <0.5, 1.4, -4.5> look_at <0, 0.6, 0> right x*image_width/image_height angle 45 }
background { rgb <0.25, 0.4, 0.7> }
light_source { <-30, 25, -20> rgb 0.9 }
plane { y, 0 pigment { rgb 0.75 } finish { ambient 0 diffuse 0.8 } }
box { <0.9, 0, -1.5>, <1.1, 1.8, 1.5> pigment { rgb <1, 0.45, 0.1> } finish { ambient 0 diffuse 0.9 } }
sphere { <0, 0.6, 0>, 0.6 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 } }
