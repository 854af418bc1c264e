sphere { 0, 1 normal { crackle 0.5 } }
// error: 1:24 unsupported: `crackle` is not supported yet
