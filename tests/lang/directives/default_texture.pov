#default { finish { ambient 0 diffuse 0.8 } }
sphere { 0, 1 }
sphere { 0, 1 pigment { rgb 1 } }
// model: objects[0].texture.finish.ambient = <0, 0, 0>
// model: objects[0].texture.finish.diffuse = 0.8
// model: objects[1].texture.finish.ambient = <0, 0, 0>
// model: objects[1].texture.finish.diffuse = 0.8
