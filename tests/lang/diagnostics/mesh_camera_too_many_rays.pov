#declare M = mesh { triangle { 0, x, y } }
camera { mesh_camera { 2 0 mesh { M } } }
// error: 2:24 mesh_camera: rays per pixel (2) must be at most the number of meshes (1) for distribution type 0
