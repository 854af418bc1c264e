#declare M = mesh { triangle { 0, x, y } }
camera { mesh_camera { 1 4 mesh { M } } }
// error: 2:26 mesh_camera: distribution type 4 is not 0, 1, 2 or 3
