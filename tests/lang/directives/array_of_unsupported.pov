// An array element that only names a declaration needing an unsupported feature is kept,
// and the error comes where that element is used, as for the name itself
// (portfolio/allnormals.pov lists `facets` among thirty normals, one used per frame)
#declare F = normal { facets coords 0.4 }
#declare G = normal { bumps 0.5 }
#declare A = array[3] { G, F, G }
sphere { 0, 1 normal { A[2] } }
// model: objects.len = 1
