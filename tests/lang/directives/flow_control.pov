// declare: Quality=2
#if (Quality > 1) #declare R = 2; #else #declare R = 1; #end
#declare I = 0;
#while (I < 3) sphere { <I,0,0>, R } #declare I = I + 1; #end
#for (J, 1, 2) box { -J, J } #end
#switch (I) #case (2) #declare S = 2; #break #case (3) #declare S = 3; #break #else #declare S = 0; #end
#ifdef (S) sphere { 0, S } #end #ifndef (Nope) plane { y, 0 } #end
// model: objects.len = 7
// model: objects[2].shape = Sphere { center: <2, 0, 0>, radius: 2 }
// model: objects[4].shape = Box { corner1: <-2, -2, -2>, corner2: <2, 2, 2> }
// model: objects[5].shape = Sphere { center: <0, 0, 0>, radius: 3 }
// value: S = 3
