camera { orthographic location <0, 0, -10> direction 2*z }
// Measured with POV-Ray 3.7: without up and right the width is |right| * distance /
// |direction|, the distance to the default look_at <0, 0, 1> here (11).
// model: camera = { right: <7.315, 0, 0>, up: <0, 5.5, 0> }
