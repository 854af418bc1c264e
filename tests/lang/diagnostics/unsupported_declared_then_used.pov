#declare Marble = texture { pigment { facets } }
sphere { 0, 1 texture { Marble } }
// error: 2:25 unsupported: `facets` is not supported yet
// note: `Marble` was declared with it at diagnostics/unsupported_declared_then_used.pov:1:39
