#version 3.7;
plane { z, 0 normal { bump_map { png "bumpmap_.png" interpolate 2 } } }
// error: 2:53 unsupported: `interpolate in a bump_map` is not supported yet
