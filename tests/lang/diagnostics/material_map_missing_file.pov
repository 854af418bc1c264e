#version 3.7;
sphere { 0, 1 texture { material_map { png "no_such_map.png" texture { pigment { rgb 1 } } } } }
// error: 2:44 cannot find the material_map image "no_such_map.png"
