#version 3.7;
plane { -z, 0 pigment { rgb 1 } normal { gradient x, 1 scale 2 } }
sphere { 0, 1 normal { bumps 0.4 scale 0.1 } }
sphere { 0, 1 texture { normal { spiral1 5, 1.6 } } }
// model: objects[0].texture.normal.amount = 1
// model: objects[1].texture.normal.amount = 0.4
// model: objects[2].texture.normal.pattern.kind = Spiral1(5)
// model: objects[2].texture.normal.amount = 1.6
