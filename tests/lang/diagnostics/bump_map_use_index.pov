#version 3.7;
plane { z, 0 normal { bump_map { png "bumpmap_.png" use_index } } }
// error: 2:53 unsupported: `use_index in a bump_map` is not supported yet
