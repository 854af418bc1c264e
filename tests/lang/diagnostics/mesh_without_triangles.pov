mesh { triangle { 0, x, 2*x } }
// error: 1:1 this mesh has no (non-degenerate) triangles
