// `internal n`: the fonts POV-Ray compiles in are the four it installs beside its include
// files (measured: each renders pixel for pixel as the file does): 1 timrom.ttf,
// 2 cyrvetic.ttf, 3 crystal.ttf, 0 and larger numbers povlogo.ttf. The second glyph of
// "A V" lands where that font's advances put it.
text { internal 1 "A V" 0.25, <0.1, 0.2, 0.3> translate x }
text { internal 2 "A V" 0.25, 0 }
text { ttf "cyrvetic.ttf" "A V" 0.25, 0 }
text { internal 7 "A V" 0.25, 0 }
text { ttf "povlogo.ttf" "A V" 0.25, 0 }
// model: objects[0].shape.Union.0[1].transform maps <0, 0, 0> to <2.198, 0.4, 0>
// model: objects[1].shape.Union.0[1].transform maps <0, 0, 0> to <0.936, 0, 0>
// model: objects[2].shape.Union.0[1].transform maps <0, 0, 0> to <0.936, 0, 0>
// model: objects[3].shape.Union.0[1].transform maps <0, 0, 0> to <4.998046875, 0, 0>
// model: objects[4].shape.Union.0[1].transform maps <0, 0, 0> to <4.998046875, 0, 0>
