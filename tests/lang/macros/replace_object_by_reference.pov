#version 3.7;
// Macros that change their caller's identifiers (POV-Ray passes bare identifiers by
// reference), including when the assignment is the last thing in the body and has no `;`.
#macro Turn_Me(Stuff, Degrees, Axis)
    #declare Stuff = object { Stuff rotate Axis*Degrees }
#end
#macro Shift(Stuff) #declare Stuff = object { Stuff translate 2*x }; #end
#declare Thing = sphere { <0, 1, 0>, 0.5 }
Turn_Me(Thing, -90, x)
Shift(Thing)
object { Thing }
// model: objects.len = 1
// rotate x*-90 takes <0,1,0> to <0,0,-1>; then the shift along x.
// model: objects[0].transform maps <0, 1, 0> to <2, 0, -1> within 1e-12
