#version 3.7;
sphere { 0, 1 texture { material_map { png "povmap.png" } } }
// error: 2:38 a material_map needs at least one texture
