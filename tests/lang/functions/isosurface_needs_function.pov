isosurface { contained_by { box { -1, 1 } } }
// error: 1:14 expected `function { ... }` (it must come first in an isosurface), found `contained_by`
