// include-path: includes/inc
#include "good.inc"
sphere { 0, 1 pigment { Red } }
// model: objects[0].texture.pigment.kind = Solid({ rgb: <1, 0, 0>, filter: 0, transmit: 0 })
