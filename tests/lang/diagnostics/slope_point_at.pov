sphere { 0, 1 pigment { slope { point_at <0, 1, 0> } } }
// error: 1:33 unsupported: `slope { point_at ... }` is not supported yet
