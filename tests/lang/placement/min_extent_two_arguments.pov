#declare S = sphere { 0, 1 }
#declare P = min_extent(S, S);
// error: 2:14 `min_extent` takes 1 argument, found 2
