#declare M = mesh { triangle { 0, x, y } }
camera { mesh_camera { 1 2 sphere { 0, 1 } } }
// error: 2:28 mesh_camera: only mesh and mesh2 objects can be cameras, found `sphere`
