#version 3.7;
// A macro whose value comes from inside an `#if` (arrays.inc's Rand_Array_Item): the
// caller's expression goes on after the macro, through the `#else` branch it skips
// (advanced/isocacti.pov: `pigment { Rand_Array_Item(Colours, R) * 0.5 }`).
#macro Pick(A, I) #if (I >= 0) A[I] #else A[0] #end #end
#declare Colours = array[2] { rgb <1, 0.5, 0>, rgb <0, 1, 1> }
#declare X = Pick(array[2] { 3, 4 }, 1) * 2 + 1;
sphere { 0, 1 pigment { Pick(Colours, 0) * 0.5 } }
// A loop's `#end` still ends an expression without `;` before it runs.
#declare I = 0;
#while (I < 3) #declare I = I + 1 #end
// value: X = 9
// value: I = 3
// model: objects[0].texture.pigment.kind.Solid.0.rgb = <0.5, 0.25, 0>
