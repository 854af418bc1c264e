// A function cannot call itself: its name is not declared until its body is read.
#declare F = function { F(x, y, z) + 1 }
// error: 2:25 unknown identifier `F`
