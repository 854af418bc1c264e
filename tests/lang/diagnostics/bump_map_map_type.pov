#version 3.7;
plane { z, 0 normal { bump_map { png "bumpmap_.png" map_type 1 } } }
// error: 2:53 unsupported: `map_type in a bump_map` is not supported yet
