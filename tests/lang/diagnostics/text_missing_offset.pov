text { ttf "timrom.ttf" "Hi" 1
  pigment { rgb 1 } }
// error: 2:3 expected an expression, found `pigment`
