sphere { 0, 1 normal { facets 0.5 } }
// error: 1:24 unsupported: `facets` is not supported yet
