// The normal variable gets the unit outward normal; a miss sets it to <0, 0, 0>.
#declare S = sphere { 0, 1 translate <0, 0, 2> }
#declare N = 0;
#declare M = 0;
#declare P = trace(S, <0, 0, -5>, z, N);
#declare Q = trace(S, <0, 3, -5>, z, M);
#declare Lo = min_extent(S);
#declare In = inside(S, <0, 0, 2.5>) + 2 * inside(S, <0, 0, 3.5>);
// value: P = <0, 0, 1>
// value: N = <0, 0, -1>
// value: Q = <0, 0, 0>
// value: M = <0, 0, 0>
// value: Lo = <-1, -1, 1>
// value: In = 1
