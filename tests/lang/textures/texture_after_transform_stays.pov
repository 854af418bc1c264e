sphere { 0, 1 scale 2 pigment { rgb 1 } }
// model: objects[0].texture.pigment.transform.forward = { matrix3: { x_axis: <1, 0, 0>, y_axis: <0, 1, 0>, z_axis: <0, 0, 1> }, translation: <0, 0, 0> }
// model: objects[0].texture.pigment.transform.inverse = { matrix3: { x_axis: <1, 0, 0>, y_axis: <0, 1, 0>, z_axis: <0, 0, 1> }, translation: <0, 0, 0> }
// model: objects[0].transform maps <1, 0, 0> to <2, 0, 0>
