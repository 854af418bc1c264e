#declare S = sphere { 0, 1 }
#declare P = trace(S, <0, 0, -5>, z, 3);
// error: 2:38 expected a variable name to receive trace's normal, found `3`
