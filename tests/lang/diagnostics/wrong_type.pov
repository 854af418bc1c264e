sphere { 0, <1,2,3> }
// error: 1:13 expected a float, found a vector
// The caret covers the whole vector.
// rendered: error: expected a float, found a vector
// rendered:  --> diagnostics/wrong_type.pov:1:13
// rendered:   |
// rendered: 1 | sphere { 0, <1,2,3> }
// rendered:   |             ^^^^^^^
