#declare Foo = 1;
sphere { 0, Fo0 }
// error: 2:13 unknown identifier `Fo0`
// hint: did you mean `Foo`?
// rendered: error: unknown identifier `Fo0`
// rendered:  --> diagnostics/unknown_identifier_hint.pov:2:13
// rendered:   |
// rendered: 2 | sphere { 0, Fo0 }
// rendered:   |             ^^^
// rendered:   = help: did you mean `Foo`?
