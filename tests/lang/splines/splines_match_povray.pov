// Values POV-Ray 3.7 prints with #debug for the same splines (vstr(3, S(t), ",", 0, 9)).
#declare S1 = spline { linear_spline 0,<0,0,0> 1,<1,2,0> 2.5,<3,1,1> 3,<4,4,-1> 5,<6,0,2> }
#declare S2 = spline { quadratic_spline 0,<0,0,0> 1,<1,2,0> 2.5,<3,1,1> 3,<4,4,-1> 5,<6,0,2> }
#declare S3 = spline { cubic_spline 0,<0,0,0> 1,<1,2,0> 2.5,<3,1,1> 3,<4,4,-1> 5,<6,0,2> }
#declare S4 = spline { natural_spline 0,<0,0,0> 1,<1,2,0> 2.5,<3,1,1> 3,<4,4,-1> 5,<6,0,2> }
#declare S0 = spline { 0,<0,0,0> 1,<1,2,0> 2.5,<3,1,1> 3,<4,4,-1> 5,<6,0,2> }
#declare L = S1(1.25);
#declare Q = S2(2.75);
#declare C = S3(1.25);
#declare N = S4(3.25);
#declare D = S0(4.5);
#declare O = S3(1.5, linear_spline);
#declare Before = S4(-1);
#declare After = S2(6);
// Unsorted entries, a repeated time (the first stays), a copy with another kind, entries
// added to a copy.
#declare U = spline { linear_spline 2,<2,0,0> 0,<0,0,0> 1,<1,5,0> }
#declare Un = U(0.5);
#declare Du = spline { linear_spline 0,<0,0,0> 1,<1,1,1> 1,<5,5,5> 2,<2,2,2> }
#declare Dup = Du(1.5);
#declare Cp = spline { U cubic_spline }
#declare Copy = Cp(0.5);
#declare Ad = spline { U 3,<9,9,9> }
#declare Added = Ad(2.5);
// A spline function, read in another function as transforms.inc and splinefunction.pov do.
#declare F = function { spline { cubic_spline -1,<0,0,0> 0,<0,1,0> 1,<1,0,0> 2,<0,0,2> } }
#declare G = function { F(x).y + 10 * F(x).x }
#declare Fv = F(0.5);
#declare Gv = G(0.5, 0, 0);
// A #local whose value a macro gives stays in the macro that declares it.
#macro Two() transform { translate 2*x } #end
#macro UseTwo() #local T = Two() #ifdef (T) #declare Ok = 1; #else #declare Ok = 0; #end #end
UseTwo()
// value: L = <1.333333333, 1.833333333, 0.166666667> within 1e-8
// value: Q = <3.479166667, 2.291666667, 0.145833333> within 1e-8
// value: C = <1.292824074, 1.949074074, 0.189814815> within 1e-8
// value: N = <4.4296875, 5.00625, -1.654296875> within 1e-8
// value: D = <5.5, 1, 1.25> within 1e-8
// value: O = <1.666666667, 1.666666667, 0.333333333> within 1e-8
// value: Before = <0, 0, 0> within 1e-8
// value: After = <6, 0, 2> within 1e-8
// value: Un = <0.5, 2.5, 0> within 1e-8
// value: Dup = <1.5, 1.5, 1.5> within 1e-8
// value: Copy = <1, 5, 0> within 1e-8
// value: Added = <5.5, 4.5, 4.5> within 1e-8
// value: Fv = <0.5625, 0.5625, -0.125> within 1e-8
// value: Gv = 6.1875
// value: Ok = 1
