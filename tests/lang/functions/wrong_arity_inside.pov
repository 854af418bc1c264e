#declare G = function(a, b) { a + b }
#declare F = function { G(x) * 2 }
// error: 2:25 `G` takes 2 arguments, found 1
