
  #frobnicate 3
// error: 2:3 unknown directive `#frobnicate`
