#version 3.7;
// A function passed to a macro by name is the function (math.inc's fn_Gradient(fn_test)).
#declare F = function(x, y, z) { 2 * x + y }
#macro Twice(Fn) function { 2 * Fn(x, y, z) } #end
#declare G = Twice(F)
#declare V = G(1, 3, 0);
// value: V = 10
