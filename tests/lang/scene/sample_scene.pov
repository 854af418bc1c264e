#version 3.7;
#declare C = rgb <1,0.5,0>;
#macro M(A) sphere { 0, A pigment { C } } #end
camera { location <0,1,-3> look_at 0 angle 60 }
light_source { <1,2,3>, 1 area_light x, z, 3, 3 }
#for (I, 0, 2) M(I + 1) #end
union { box { -1, 1 } sphere { y, 0.5 finish { phong 1 } } scale 2 }
plane { y, 0 pigment { checker rgb 1, rgb 0 } }
// model: objects.len = 5
// model: lights.len = 1
