#declare S = seed(1);
#declare V = rand(S + 3);
// error: 2:19 `rand` needs a stream made by `seed`
