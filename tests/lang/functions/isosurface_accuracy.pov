isosurface { function { x } accuracy 0 }
// error: 1:1 the isosurface's accuracy 0 must be positive
