text { "timrom.ttf" "Hi" 1, 0 }
// error: 1:8 expected `ttf` and the font file's name, found string "timrom.ttf"
