#declare F = function { internal(53) }
sphere { 0, F(1, 2, 3) }
// error: 2:13 unsupported: internal function 53 is not supported yet
// note: `F` was declared with it at functions/unsupported_internal.pov:1:25
