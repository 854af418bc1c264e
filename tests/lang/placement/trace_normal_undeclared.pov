#declare S = sphere { 0, 1 }
#declare P = trace(S, <0, 0, -5>, z, Nrm);
// error: 2:38 trace's normal variable `Nrm` must be declared before the call
