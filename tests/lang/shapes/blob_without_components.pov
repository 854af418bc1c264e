blob { threshold 0.5 pigment { rgb 1 } }
// error: 1:1 this blob has no components
