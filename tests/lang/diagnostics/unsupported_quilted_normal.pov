sphere { 0, 1 normal { quilted 0.5 } }
// error: 1:24 unsupported: `quilted` is not supported yet
