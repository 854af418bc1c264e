// shapes2.inc uses shapes.inc's objects without including it; POV-Ray fails too.
#include "colors.inc"
#include "shapes.inc"
#include "shapes2.inc"
sphere { 0, 1 }
// model: objects.len = 1
