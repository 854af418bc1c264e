// shapes2.inc uses shapes.inc's objects without including it; POV-Ray fails too.
#include "colors.inc"
#include "shapes.inc"
#include "rand.inc"
sphere { 0, 1 }
// model: objects.len = 1
