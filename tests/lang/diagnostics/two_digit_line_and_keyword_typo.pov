// error: 12:1 unknown identifier `sphree`
// hint: did you mean `sphere`?
// rendered: error: unknown identifier `sphree`
// rendered:   --> diagnostics/two_digit_line_and_keyword_typo.pov:12:1
// rendered:    |
// rendered: 12 | sphree { 0, 1 }
// rendered:    | ^^^^^^
// rendered:    = help: did you mean `sphere`?
// The two-digit line number widens the gutter.


sphree { 0, 1 }
