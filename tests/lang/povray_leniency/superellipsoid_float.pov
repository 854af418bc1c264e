#version 3.7;
// `superellipsoid { e }` reads as <e, e> (advanced/cliche.pov; measured: the same image).
superellipsoid { 0.15 }
// model: objects[0].shape = Superellipsoid { east_west: 0.15, north_south: 0.15 }
