// A glyph per character with an outline (the space has none); POV-Ray adds ".ttf" to a
// font name it cannot find as given. Strings are read as Unicode whatever the charset
// (`\u` escapes included).
text { ttf "timrom.ttf" "A V" 0.25, <0.1, 0.2, 0.3> pigment { rgb 1 } translate x }
text { ttf "cyrvetic" "\u00e9" 1, 0 }
global_settings { charset utf8 }
text { ttf "cyrvetic", "é", 1, 0 }
#declare S = "a\u0041\u00";
// model: objects.len = 3
// model: objects[0].shape.Union.0.len = 2
// model: objects[0].shape.Union.0[0].shape.Glyph.0.depth = 0.25
// model: objects[0].shape.Union.0[0].transform maps <0.006, 0, 0> to <1, 0, 0>
// model: objects[0].shape.Union.0[0].transform maps <0, 0.5, 0> to <0.994, 0, 0.5>
// model: objects[0].shape.Union.0[1].transform maps <0, 0, 0> to <2.198, 0.4, 0>
// model: objects[1].shape.Union.0.len = 1
// model: objects[2].shape.Union.0.len = 1
// value: S = "aAu00"
