// options: skip-unsupported
ovus { 1, 0.5 }
photons { count 3 }
#declare T = ovus { 1, 0.5 }
object { T translate x }
union { sphere { 0, 1 } parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> } }
sphere { 0, 1 photons { target } }
// model: objects.len = 2
// warning: 2:1 unsupported: `ovus` is not supported yet; it is left out
// warning: 3:1 unsupported: `photons` is not supported yet; it is left out
// warning: 5:10 unsupported: `ovus` is not supported yet; the object is left out
// warning: 6:25 unsupported: `parametric` is not supported yet; it is left out
