sphere { 0, 1 global_lights on }
// error: 1:15 `global_lights` only applies to a light_group
