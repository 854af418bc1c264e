#declare M = mesh { triangle { 0, x, y } }
camera { mesh_camera { 1 3 mesh { M } } }
// error: 2:28 mesh_camera: distribution type 3 looks pixels up in the uv map, and this mesh has no uv_vectors
