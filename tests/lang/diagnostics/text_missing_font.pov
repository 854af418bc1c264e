text { ttf "no_such_font.ttf" "Hello" 0.2, 0 }
// error: 1:12 cannot find the font "no_such_font.ttf"
