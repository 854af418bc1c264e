// Total internal reflection in a filtering glass box resting on a floor plane, and a
// transparent fading sphere whose inner highlight is seen through its front.
// Checks: under total internal reflection the light is not filtered by the surface and
// the finish's reflection plus the reflected rest add to one; interior fade applies to what
// a surface lets through from beyond, not to its own highlight or internal reflection; a box
// face lying exactly on the floor plane meets the plane first (POV-Ray's tie rule).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 20 adc_bailout 0 }
camera { location <0, 5, -20> angle 16 right x*4/3 look_at <0, 0.3, 0> }
sky_sphere {
  pigment { gradient y color_map { [0 rgb <1, 0.2, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0.2, 1>] }
    scale 2 translate -y }
}
light_source { <-20, 40, -30> rgb 1 }
plane { y, -1
  pigment { checker rgb <0.2, 0.6, 0.3> rgb <0.5, 0.8, 0.9> scale <32000, 1, 0.5> }
  finish { ambient 0.1 diffuse 0.6 }
}
box { -1, 1 rotate 45*y translate -1.6*x
  texture { pigment { rgbf <1, 1, 1, 0.5> } finish { ambient 0 diffuse 0 reflection 0.1 } }
  interior { ior 1.6 }
}
sphere { <1.6, 0.2, 0>, 1.2
  texture { pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 phong 1 phong_size 200 } }
  interior { ior 1.05 fade_distance 2 fade_power 1 }
}
