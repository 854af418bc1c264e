// `#ifdef (A[i])` asks whether that element is set, and a pigment or finish block may be an
// element of an array of them (as portfolio/html_gen.inc and the portfolio scenes write).
#declare Names = array[3];
#declare Names[1] = "set";
#declare Count = 0;
#ifdef (Names[0]) #declare Count = Count + 1; #end
#ifdef (Names[1]) #declare Count = Count + 10; #end
#ifndef (Names[2]) #declare Count = Count + 100; #end
#if (Count != 110) #error concat("ifdef on elements: ", str(Count, 0, 0)) #end
#declare Pigments = array[2] { pigment { rgb <1, 0, 0> }, pigment { rgb <0, 0, 1> } }
#declare Finishes = array[2] { finish { ambient 0.3 }, finish { phong 0.7 } }
sphere { 0, 1 pigment { Pigments[1] } finish { Finishes[1] } }
// model: objects[0].texture.Some.0.pigment.kind.Solid.0.rgb = <0, 0, 1>
// model: objects[0].texture.Some.0.finish.phong = 0.7
