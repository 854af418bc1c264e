// POV-Ray reads `<` as less-than only inside parentheses: `poly { 4 <...> }` is the order 4
// and its coefficients (objects/primitiv.pov), while `(2 < 3)` still compares.
poly { 4
   < 1, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0> }
#if ((2 < 3) != 1) #error "comparison" #end
// model: objects.len = 1
// model: objects[0].shape.Poly.order = 4
