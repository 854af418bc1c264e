// colors.inc is found on POV-Ray's include path, but it is a scene file.
text { ttf "colors.inc" "Hello" 0.2, 0 }
// error: 2:12 "colors.inc" is not a TrueType font (unknown magic)
