#version 3.7;
plane { z, 0 normal { bump_map { png "bumpmap_.png" map_type 3 } } }
// error: 2:53 unsupported: `map_type other than 0, 1, 2, 5` is not supported yet
