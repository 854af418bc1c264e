sphere { <0,0,0>, 1
    pigment { rgb 1 }

    camera { location <0,1,-3> }
// error: 4:5 expected `}` to close the sphere, found `camera`
// rendered: error: expected `}` to close the sphere, found `camera`
// rendered:  --> diagnostics/missing_close_brace.pov:4:5
// rendered:   |
// rendered: 4 |     camera { location <0,1,-3> }
// rendered:   |     ^^^^^^
