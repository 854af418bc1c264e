// trace, min_extent, max_extent and inside against POV-Ray 3.7: the `debug:` lines below
// are what `povray +W8 +H8 +I<this file>` printed for this file (POV-Ray 3.7.0.10), copied
// as they came, except the plane's extent, whose line POV-Ray cut short (its concat limit).
#version 3.7;
#declare S = sphere { <1, 2, 3>, 1.5 }
#declare B = box { <-1, -2, -3>, <1, 2, 3> rotate <0, 30, 0> translate <0.5, 0, 0> }
#declare D = difference { sphere { 0, 2 } box { <-3, -3, -3>, <3, 3, 0> } }
#declare P = plane { y, 1 }
#declare U = union { sphere { <-2, 0, 0>, 1 } box { <1, -1, -1>, <3, 0.5, 2> } }
#declare I = intersection { sphere { 0, 2 } box { <-1, -1, -1>, <5, 5, 5> } }
#declare T = torus { 2, 0.5 scale <1, 2, 1> rotate <90, 0, 0> }
#declare Q = poly { 6, <1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,6,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1,0,0,0,0,0,-1> bounded_by { sphere { 0, 1.8 } } }
#declare R = sphere { 0, 1 scale <1, 2, 3> rotate <0, 0, 45> }
#declare N = <9, 9, 9>;
#macro Tr(O, A, Dd)
  #declare N = <9, 9, 9>;
  #local H = trace(O, A, Dd, N);
  #debug concat("trace ", vstr(3, H, ",", 0, 6), " normal ", vstr(3, N, ",", 0, 6), "\n")
#end
#macro Ex(O)
  #debug concat("extent ", vstr(3, min_extent(O), ",", 0, 6), " / ", vstr(3, max_extent(O), ",", 0, 6), "\n")
#end
#macro In(O, A)
  #debug concat("inside ", str(inside(O, A), 0, 0), "\n")
#end
Tr(S, <1, 2, -10>, z)
Tr(S, <1, 2, 3>, <0, 0, 2>)
Tr(S, <1, 2, -10>, -z)
Tr(S, <1.5, 2.5, -10>, <0, 0, 1>)
Tr(B, <-10, 0.3, 0.2>, x)
Tr(D, <0, 0, -10>, z)
Tr(D, <0.5, 0.2, 0>, <0, 0, 1>)
Tr(P, <3, 5, 1>, <1, -2, 0.5>)
Tr(U, <-10, 0.2, 0.1>, x)
Tr(T, <-10, 0, 0>, x)
Tr(Q, <-10, 0.1, 0.2>, x)
Tr(Q, <-10, 0.1, 0.2>, <1, 0.05, 0>)
Tr(R, <0, 0, -10>, z)
Ex(S) Ex(B) Ex(D) Ex(P) Ex(U) Ex(I) Ex(T) Ex(Q) Ex(R)
In(S, <1, 2, 3>) In(S, <1, 2, 4.6>) In(D, <0, 0, 1>) In(D, <0, 0, -1>) In(P, <0, 0, 0>) In(P, <0, 2, 0>)
In(U, <2, 0, 0>) In(U, <0, 0, 0>) In(I, <0.5, 0.5, 0.5>) In(I, <-1.5, 0, 0>) In(T, <2, 0, 0>) In(T, <0, 2, 0.2>) In(Q, <0.5, 0.5, 0.5>) In(Q, <0.9, 0.9, 0>)
// debug: trace 1.000000,2.000000,1.500000 normal 0.000000,0.000000,-1.000000
// debug: trace 1.000000,2.000000,4.500000 normal 0.000000,0.000000,1.000000
// debug: trace 0.000000,0.000000,0.000000 normal 0.000000,0.000000,0.000000
// debug: trace 1.500000,2.500000,1.677124 normal 0.333333,0.333333,-0.881917
// debug: trace -0.539230,0.300000,0.200000 normal -0.866025,0.000000,0.500000
// debug: trace 0.000000,0.000000,0.000000 normal -0.000000,-0.000000,-1.000000
// debug: trace 0.500000,0.200000,1.926136 normal 0.250000,0.100000,0.963068
// debug: trace 5.000000,1.000000,2.000000 normal 0.000000,1.000000,0.000000
// debug: trace -2.974679,0.200000,0.100000 normal -0.974679,0.200000,0.100000
// debug: trace -2.500000,0.000000,0.000000 normal -1.000000,0.000000,0.000000
// debug: trace -0.999589,0.100000,0.200000 normal -0.999959,0.008013,0.004322
// debug: trace -0.982891,0.550855,0.200000 normal -0.987522,0.097887,0.123366
// debug: trace 0.000000,0.000000,-3.000000 normal 0.000000,0.000000,-1.000000
// debug: extent -0.500000,0.500000,1.500000 / 2.500000,3.500000,4.500000
// debug: extent -1.866025,-2.000000,-3.098076 / 2.866025,2.000000,3.098076
// debug: extent -2.000000,-2.000000,-2.000000 / 2.000000,2.000000,2.000000
// debug: extent -10000000000.000000,-10000000000.000000,-10000000000.000000 / 10000000000.000000,10000000000.000000,10000000000.000000
// debug: extent -3.000000,-1.000000,-1.000000 / 3.000000,1.000000,2.000000
// debug: extent -1.000000,-1.000000,-1.000000 / 2.000000,2.000000,2.000000
// debug: extent -2.500000,-2.500000,-1.000000 / 2.500000,2.500000,1.000000
// debug: extent -1.800000,-1.800000,-1.800000 / 1.800000,1.800000,1.800000
// debug: extent -2.121320,-2.121320,-3.000000 / 2.121320,2.121320,3.000000
// debug: inside 1
// debug: inside 0
// debug: inside 1
// debug: inside 0
// debug: inside 1
// debug: inside 0
// debug: inside 1
// debug: inside 0
// debug: inside 1
// debug: inside 0
// debug: inside 1
// debug: inside 1
// debug: inside 1
// debug: inside 0
