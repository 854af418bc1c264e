cylinder { 0, y, 1 open }
cone { 0, 1, y*2, 0.5 }
disc { x, y*2, 1, 0.5 }
torus { 2, 0.5 sturm }
quadric { <1,1,1>, 0, 0, -1 }
triangle { 0, x, y }
smooth_triangle { 0, z, x, z, y, z }
mesh { triangle { 0, x, y } triangle { 0, x, 2*x } inside_vector z }
polygon { 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,0> }
// model: objects[0].shape.Cylinder.0 = Cylinder { base: <0, 0, 0>, cap: <0, 1, 0>, radius: 1, open: true }
// model: objects[1].shape.Cone.0 = Cone { base: <0, 0, 0>, base_radius: 1, cap: <0, 2, 0>, cap_radius: 0.5, open: false }
// model: objects[2].shape.Disc.0 = Disc { center: <1, 0, 0>, normal: <0, 1, 0>, radius: 1, hole_radius: 0.5 }
// model: objects[3].shape = Torus { major: 2, minor: 0.5 }
// model: objects[4].shape.Quadric.0 = [1, 1, 1, 0, 0, 0, 0, 0, 0, -1]
// model: objects[5].shape.Triangle.0[1] = <1, 0, 0>
// model: objects[6].shape.SmoothTriangle.0.normals[2] = <0, 0, 1>
// The degenerate triangle is dropped silently, as POV-Ray does in meshes.
// model: objects[7].shape.Mesh.0.faces.len = 1
// model: objects[7].shape.Mesh.0.inside_vector = Some(<0, 0, 1>)
// model: objects[8].shape.Polygon.points.len = 5
// model: objects[8].shape.Polygon.points[2] = <1, 1, 0>
