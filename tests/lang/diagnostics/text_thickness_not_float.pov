text { ttf "timrom.ttf" "Hi" "thick", 0 }
// error: 1:30 expected a float, found a string
