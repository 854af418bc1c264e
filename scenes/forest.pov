// A forest: one declared tree of Parts objects placed Trees x Trees times. The tree is
// shared, not copied: every placement is an instance of one prototype (issue 16). Its
// leaves are patterned, so each placement's texture moves with it. Bigger forests:
// --declare Trees=100 --declare Parts=1000 (10^4 trees of 10^3 parts).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (Trees) #declare Trees = 12; #end
#ifndef (Parts) #declare Parts = 120; #end
camera { location <0, 2 + Trees * 0.25, -Trees * 1.3> look_at <0, 1, 0> angle 60 }
light_source { <-30, 60, -40> color rgb 1 }
light_source { <20, 30, -50> color rgb 0.3 shadowless }
plane { y, 0 pigment { color rgb <0.45, 0.4, 0.3> } }
#declare R = seed(7);
#declare Tree = union {
  cone { <0, 0, 0>, 0.12, <0, 2.2, 0>, 0.04 pigment { color rgb <0.35, 0.22, 0.1> } }
  #declare I = 1;
  #while (I < Parts)
    #declare H = 0.9 + 2 * rand(R);
    #declare D = (3.1 - H) * 0.35 * sqrt(rand(R));
    sphere { <D, H, 0>, 0.16 rotate y * 360 * rand(R) }
    #declare I = I + 1;
  #end
  pigment { leopard color_map { [0 color rgb <0.1, 0.35, 0.08>] [1 color rgb <0.6, 0.8, 0.15>] } scale 0.05 }
}
#declare I = 0;
#while (I < Trees)
  #declare J = 0;
  #while (J < Trees)
    object {
      Tree
      rotate y * 360 * rand(R)
      scale 0.7 + 0.6 * rand(R)
      translate <(I - Trees / 2 + rand(R)) * 2, 0, (J - Trees / 2 + rand(R)) * 2>
    }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
