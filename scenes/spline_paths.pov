// The language's splines: beads along one set of entries read as linear, quadratic, cubic
// and natural splines (one row each), a cubic read as linear at the call, and a wall
// coloured by a spline function (as POV-Ray's splinefunction.pov does).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.6, -9> look_at <0, 1.3, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 8, -6> color rgb 1 }

#declare Path = spline { linear_spline
  0, <-3, 0, 0>  1, <-2, 0.6, 0>  2.5, <0, 0.2, 0>  3, <1, 0.9, 0>  5, <3, 0, 0> }
#declare Kinds = array[4] { spline { Path }, spline { Path quadratic_spline },
                            spline { Path cubic_spline }, spline { Path natural_spline } }
#declare Colours = array[4] { rgb <0.9, 0.3, 0.2>, rgb <0.2, 0.7, 0.3>, rgb <0.2, 0.4, 0.9>,
                              rgb <0.9, 0.8, 0.2> }
#for (K, 0, 3)
  #declare S = Kinds[K];
  #for (T, -0.5, 5.5, 0.25)
    sphere { S(T) + <0, 0.75 * K, 0>, 0.12 pigment { Colours[K] } finish { phong 0.5 } }
  #end
#end
#declare C = Kinds[2];
#for (T, 0, 5, 0.5)
  sphere { C(T, linear_spline) + <0, 3.05, 0>, 0.08 pigment { rgb 1 } }
#end

#declare Ramp = function {
  spline { cubic_spline -0.25, <0, 0, 0> 0, <0.1, 0.2, 0> 0.5, <0.9, 0.5, 0> 1, <0.2, 1, 0>
           1.25, <0, 0, 0> } }
box { <-4, -1, 1>, <4, 4, 1.2>
  pigment { function { Ramp(x / 8 + 0.5).x } color_map { [0 rgb <0.05, 0.1, 0.4>] [1 rgb <1, 0.85, 0.5>] } }
  finish { ambient 0.2 diffuse 0.7 } }
plane { y, -0.3 pigment { rgb 0.6 } }
