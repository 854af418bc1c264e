#declare M = mesh { triangle { 0, x, y } }
camera { mesh_camera { 0 1 mesh { M } } }
// error: 2:24 mesh_camera: rays per pixel is 0; it must be at least 1
