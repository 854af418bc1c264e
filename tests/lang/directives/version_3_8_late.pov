sphere { 0, 1 }
#version 3.8;
sphere { 0, 1 }
// model: objects[1].texture = None
// warning: 2:10 POV-Ray 3.7 refuses `#version 3.8`; penumbra reads the scene as 3.7, default ambient unchanged (not the first statement)
