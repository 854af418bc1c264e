camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 2*x up y angle 90 }
// Measured with POV-Ray 3.7: with `angle` an orthographic camera is as wide as a
// perspective one at the look_at distance (2 * 10 * tan 45 = 20); up scales alike.
// model: camera = { right: <20, 0, 0>, up: <0, 10, 0> }
