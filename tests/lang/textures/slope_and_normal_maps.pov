#version 3.7;
plane { -z, 0 normal { gradient x, 1 slope_map { [0 <0, 0>] [0.5, <1, -2>] [1 0.5] } } }
plane { -z, 0 normal { gradient x normal_map { [0 gradient y, -10] [1 gradient x, -2.5 scale 2] } rotate z*30 } }
// model: objects[0].texture.normal.slope_map = [{ value: 0, height: 0, slope: 0 }, { value: 0.5, height: 1, slope: -2 }, { value: 1, height: 0.5, slope: 0.5 }]
// model: objects[1].texture.normal.normal_map.len = 2
// The rotation written after the map turns the entries too (measured with povray).
// model: objects[1].texture.normal.transform unmaps <1, 0, 0> to <0.8660254037844387, -0.5, 0> within 1e-12
// model: objects[1].texture.normal.normal_map[0].1.transform unmaps <1, 0, 0> to <0.8660254037844387, -0.5, 0> within 1e-12
