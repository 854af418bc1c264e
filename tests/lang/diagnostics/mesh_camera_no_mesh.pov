#declare M = mesh { triangle { 0, x, y } }
camera { mesh_camera { 1 0 } }
// error: 2:10 mesh_camera: no mesh { } to shoot rays from
