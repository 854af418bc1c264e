#include "transforms.inc"
#declare M = mesh { triangle { 0, x, y uv_vectors <0, 0>, <1, 0>, <0, 1> } }
camera { mesh_camera { 1 3 5 mesh { M translate z } smooth } location <0, 0, -0.01> direction -z }
#declare V = vtransform(<1, 2, 3>, transform { translate x scale 2 });
// model: camera.projection = Mesh
// model: camera.mesh.rig.max_distance = Some(5.0)
// model: camera.mesh.rig.smooth = true
// model: camera.mesh.rig.meshes[0].faces[0].corners[1] = <1, 0, 1>
// model: camera.mesh.offset = -0.01
// model: camera.mesh.reverse = true
// value: V = <4, 4, 6>
