#declare G = function(a, b) { a + b }
#declare V = G(1, 2, 3);
// error: 2:14 `G` takes 2 arguments, found 3
