#macro M(A)
  sphere { 0, A pigment { Nope } }
#end
M(1)
// error: 2:27 unknown identifier `Nope`
// note: in macro `M` called here at macros/macro_trace.pov:4:1
// rendered: error: unknown identifier `Nope`
// rendered:  --> macros/macro_trace.pov:2:27
// rendered:   |
// rendered: 2 |   sphere { 0, A pigment { Nope } }
// rendered:   |                           ^^^^
// rendered:   = note: in macro `M` called here at macros/macro_trace.pov:4:1
