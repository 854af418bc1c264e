
#include "colours.inc"
// include-path: includes/inc
// error: includes/inc/colours.inc:2:20 expected `>` to close the vector, found `;`
// note: in file `includes/inc/colours.inc` included here at includes/include_chain_error.pov:2:1
// rendered: error: expected `>` to close the vector, found `;`
// rendered:  --> includes/inc/colours.inc:2:20
// rendered:   |
// rendered: 2 | #declare Bad = <1,2;
// rendered:   |                    ^
// rendered:   = note: in file `includes/inc/colours.inc` included here at includes/include_chain_error.pov:2:1
