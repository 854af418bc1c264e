#declare A = 3;
#declare P = trace(A, <0, 0, 0>, z);
// error: 2:20 `trace` needs an object as its first argument, found a float
