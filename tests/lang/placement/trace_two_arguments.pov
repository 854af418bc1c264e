#declare S = sphere { 0, 1 }
#declare P = trace(S, <0, 0, -5>);
// error: 2:14 `trace` takes 3 or 4 arguments
