// A declaration whose value needs an unsupported feature is skipped as written; a macro
// call's value ends at its `)`, not at the end of the object after it (blkhole.pov lost
// its only object this way and rendered black without an error).
#macro M(A) object { ovus { A, 0.5 } } #end
#declare B = M(1)
sphere { 0, 1 }
#declare C = (1 + 2) * 3
sphere { 0, C }
// model: objects.len = 2
// model: objects[1].shape.Sphere.radius = 9
