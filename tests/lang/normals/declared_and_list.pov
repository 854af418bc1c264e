#declare N = normal { ripples 0.7 }
#declare M = normal { N scale 2 }
plane { y, 0 normal { checker normal { N } normal { M } } }
// model: objects[0].texture.normal.normal_map.len = 2
// model: objects[0].texture.normal.normal_map[1].1.amount = 0.7
// model: objects[0].texture.normal.normal_map[0].0 = 0
// model: objects[0].texture.normal.normal_map[1].0 = 1
