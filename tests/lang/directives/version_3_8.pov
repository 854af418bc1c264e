#version 3.8;
sphere { 0, 1 pigment { rgb 1 } }
sphere { 0, 1 finish { ambient 0.3 } }
#version 3.7;
#version 3.8;
#declare V = version;
// value: V = 3.8
// model: objects[0].texture.finish = { ambient: <0, 0, 0>, diffuse: 0.6 }
// model: objects[1].texture.finish = { ambient: <0.3, 0.3, 0.3> }
// warning: 1:10 POV-Ray 3.7 refuses `#version 3.8`; penumbra reads the scene as 3.7, default ambient 0 (as POV-Ray 3.8 does)
