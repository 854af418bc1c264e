// CSG with many children: a slab with 2,500 holes (a difference of 2,501 shapes) and a
// merge of 900 glass-free spheres, each child tested only where its box is met (issue 16).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 14, -16> look_at <0, 0, 0> angle 50 }
light_source { <-10, 30, -20> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.8 color rgb 0.3 scale 2 } }
difference {
  box { <-10, -0.5, -10>, <10, 0.5, 10> }
  #declare I = 0;
  #while (I < 50)
    #declare J = 0;
    #while (J < 50)
      cylinder { <-9.8 + I * 0.4, -1, -9.8 + J * 0.4>, <-9.8 + I * 0.4, 1, -9.8 + J * 0.4>, 0.15 }
      #declare J = J + 1;
    #end
    #declare I = I + 1;
  #end
  pigment { color rgb <0.9, 0.6, 0.3> }
}
merge {
  #declare I = 0;
  #while (I < 30)
    #declare J = 0;
    #while (J < 30)
      sphere { <-6 + I * 0.4, 1.5 + 0.3 * sin(I + J), -3 + J * 0.2>, 0.3 }
      #declare J = J + 1;
    #end
    #declare I = I + 1;
  #end
  pigment { color rgb <0.3, 0.5, 0.9> }
}
