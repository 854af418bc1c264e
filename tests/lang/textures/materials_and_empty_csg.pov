#declare M = material { texture { pigment { rgb 1 } } interior { ior 1.5 } }
#declare A = array[1] { M }
sphere { 0, 1 material { A[0] } }
union { }
union { #for (I, 1, 0) sphere { 0, 1 } #end pigment { rgb 1 } }
// model: objects.len = 1
// model: objects[0].interior.ior = 1.5
// model: objects[0].texture.pigment.kind = Solid({ rgb: <1, 1, 1>, filter: 0, transmit: 0 })
