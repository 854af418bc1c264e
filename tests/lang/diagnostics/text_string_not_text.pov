#declare N = 3;
text { ttf "timrom.ttf" N 0.2, 0 }
// error: 2:25 expected the text as a string, found a float
