blob {
  sphere { 0, 1, 1 pigment { rgb 1 } }
}
// error: 2:20 unsupported: `textures on blob components` is not supported yet
