#version 3.7;
#declare Red = texture { pigment { rgb <1,0,0> } }
plane { y, 0 texture { gradient x texture_map { [0 Red] [1 pigment { rgb <0,0,1> } finish { ambient 0 }] } } }
// model: objects[0].texture.map.entries.len = 2
// model: objects[0].texture.map.entries[0].1.pigment.kind = Solid({ rgb: <1, 0, 0>, filter: 0, transmit: 0 })
// model: objects[0].texture.map.entries[1].1.finish.ambient = <0, 0, 0>
