// User-defined functions: every expected value is what POV-Ray 3.7.0.10 printed for the
// same lines (`#debug` with str(..., 0, 6)).
#include "functions.inc"
#declare F = function { x*x + y }
#declare G = function(a, b) { select(a, 1, 2, 3) + b }
#declare H = function { G(x, y) * 2 }
#declare P = function { pigment { gradient x color_map { [0 rgb 0][1 rgb <1, 0.5, 0.25>] } } }
#declare Q = function { P(x, y, z).green + 1 }
#declare C = 2;
#declare K = function { x * C }
#declare C = 5;
#declare SM = function { sum(i, 1, x, i*i) }
#declare PR = function { prod(i, 1, x, i) }
#declare LG = function { (x & y) + 10*(x | y) + 1000*(x = y) }
#declare MD = function { mod(x, 3) + 10*int(y) + 100*floor(z) }
#declare UV = function { u + 10*v }
#declare MX = function { max(x, y, z) + min(x, y) }
#debug concat(str(F(3, 1, 0), 0, 6), " ", str(G(-1, 0), 0, 6), " ", str(G(0, 0), 0, 6), " ", str(G(1, 0), 0, 6), "\n")
#debug concat(str(H(1, 1, 0), 0, 6), " ", str(P(0.5, 0, 0).green, 0, 6), " ", str(Q(0.5, 0, 0), 0, 6), " ", str(K(1, 0, 0), 0, 6), "\n")
#debug concat(str(SM(3, 0, 0), 0, 6), " ", str(PR(4, 0, 0), 0, 6), " ", str(LG(1, 0, 0), 0, 6), " ", str(LG(0.5, 0.5, 0), 0, 6), "\n")
#debug concat(str(MD(-4, -1.5, -1.5), 0, 6), " ", str(UV(1, 2, 3), 0, 6), " ", str(MX(1, 5, 3), 0, 6), "\n")
#debug concat(str(f_sphere(1, 2, 2, 1), 0, 6), " ", str(f_torus(3, 1, 0, 2, 0.5), 0, 6), " ", str(f_rounded_box(2, 2, 2, 0.1, 1, 1, 1), 0, 6), " ", str(f_superellipsoid(0.5, 0.5, 0.5, 0.5, 1), 0, 6), "\n")
#declare GP = function { pattern { gradient x } }
#debug concat(str(GP(0.5, 0, 0), 0, 6), " ", str(GP(1, 0, 0), 0, 6), " ", str(GP(1.5, 0, 0), 0, 6), " ", str(f_checker(1.3, 0.4, 0.5), 0, 6), "\n")
// A list pattern's value is its entry's index: hexagon 0, 2, 1, checker 0, 1.
#declare HX = function { pattern { hexagon } }
#declare CK = function { pattern { checker } }
#debug concat(str(HX(0, 0, 0), 0, 6), " ", str(HX(1.5, 0, 0.3), 0, 6), " ", str(HX(0, 0, 1.7), 0, 6), " ", str(CK(1.5, 0.5, 0.5), 0, 6), "\n")
// debug: 10.000000 1.000000 2.000000 3.000000
// debug: 8.000000 0.250000 1.250000 2.000000
// debug: 14.000000 24.000000 10.000000 1011.000000
// debug: -211.000000 21.000000 6.000000
// debug: 2.000000 0.914214 1.805255 0.223113
// debug: 0.500000 1.000000 0.500000 1.000000
// debug: 0.000000 2.000000 1.000000 1.000000
