#version 3.7;
#declare M = color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] }
plane { y, 0 pigment { gradient x color_map { M } } }
// model: objects[0].texture.pigment.kind.ColourMap.map.len = 2
// model: objects[0].texture.pigment.kind.ColourMap.map[1].1.rgb = <0, 0, 1>
