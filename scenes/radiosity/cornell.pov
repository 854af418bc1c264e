// Radiosity, diffuse interreflection: a Cornell-like box (red and green side walls, white
// floor, ceiling and back) lit by one point light under the ceiling; the shadows are filled
// and the walls bleed their colour onto the white boxes through three diffuse bounces.
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
    recursion_limit 3
  }
  #end
}
camera { location <0, 1, -3.4> look_at <0, 1, 0> right x*image_width/image_height angle 40 }
light_source { <0, 1.9, 0> rgb 1 }
#declare Wall = finish { ambient 0 diffuse 0.8 }
#declare White = texture { pigment { rgb 0.8 } finish { Wall } }
box { <-1, -0.01, -1>, <1, 0, 1> texture { White } }               // floor
box { <-1, 2, -1>, <1, 2.01, 1> texture { White } }                // ceiling
box { <-1, 0, 1>, <1, 2, 1.01> texture { White } }                 // back
box { <-1.01, 0, -1>, <-1, 2, 1> pigment { rgb <0.8, 0.1, 0.1> } finish { Wall } }
box { <1, 0, -1>, <1.01, 2, 1> pigment { rgb <0.1, 0.8, 0.1> } finish { Wall } }
box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate y*20 translate <-0.35, 0, 0.35> texture { White } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate -y*18 translate <0.4, 0, -0.3> texture { White } }
