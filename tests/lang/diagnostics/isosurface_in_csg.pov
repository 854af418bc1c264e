difference {
  sphere { 0, 1 }
  isosurface { function { x } }
}
// error: 3:3 unsupported: `isosurface` is not supported yet
