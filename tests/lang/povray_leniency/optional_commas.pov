#version 3.7;
// Commas POV-Ray leaves optional: between a reflection's minimum and maximum
// (gamma/gamma_showcase.pov; measured: `{ 0.3 0.8 }` renders as `{ 0.3, 0.8 }`) and
// between macro arguments (incdemo/shapes.pov passes an object, then `-y`).
#macro Sum(A, B, C) (A + B + C) #end
#declare V = Sum(1 2, -4);
#macro Place(O, Offset) object { O translate Offset } #end
object { Place(sphere { 0, 1 } -y) }
sphere { 0, 1 finish { reflection { 0.3 0.8 } } }
// value: V = -1
// model: objects[0].transform maps <0, 0, 0> to <0, -1, 0>
// model: objects[1].texture.finish.reflection.min = <0.3, 0.3, 0.3>
// model: objects[1].texture.finish.reflection.max = <0.8, 0.8, 0.8>
