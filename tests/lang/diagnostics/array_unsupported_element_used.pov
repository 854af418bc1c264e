#declare F = normal { facets coords 0.4 }
#declare A = array[2] { F, F }
sphere { 0, 1 normal { A[1] } }
// error: 3:24 unsupported: `facets` is not supported yet
