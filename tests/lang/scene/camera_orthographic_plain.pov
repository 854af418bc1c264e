camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 4*x up 3*y }
// Measured with POV-Ray 3.7: with up or right and no angle, they are the view's size.
// model: camera = { right: <4, 0, 0>, up: <0, 3, 0> }
