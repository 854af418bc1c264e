// The token stream looks up only the names that may be macros: a name read as a float
// before any macro exists, a macro declared afterwards, a float name later made a macro,
// and a macro called inside a loop whose other names stay plain.
#declare A = 1;
#declare B0 = A + 1;
#macro Two() 2 #end
#declare B = A + Two();
#declare M = 5;
#declare C0 = M;
#macro M() 7 #end
#declare C = M() + A;
#declare S = 0;
#declare I = 0;
#while (I < 3)
  #declare S = S + Two() * I + A;
  #declare I = I + 1;
#end
// value: B0 = 2
// value: B = 3
// value: C0 = 5
// value: C = 8
// value: S = 9
