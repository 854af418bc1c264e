// Include files declare many things a scene never uses.
#declare Marble = texture { pigment { marble color_map { [0 rgb 0] [1 rgb 1] } } }
#declare Layered = texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } }
#declare Q = quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 }
sphere { 0, 1 }
// model: objects.len = 1
