triangle { 0, x, 2*x } union { triangle { 0, y, 2*y } sphere { 0, 1 } }
// model: objects.len = 1
// warning: 1:1 degenerate triangle; it is left out
// warning: 1:32 degenerate triangle; it is left out
