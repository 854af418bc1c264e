plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } } }
// error: 1:92 expected `tile2` and the second tile's texture, found `}`
