// A function height field: point (i, j) reads f(i / (W - 1), 1 - j / (H - 1), 0), wrapped
// into [0, 1] as POV-Ray's trace showed (2x - 0.5 gives 0.5, 0, 0.5, 1, 0.5 along x).
height_field { function 5, 3 { 2 * x - 0.5 + 0 * y } smooth }
// model: objects[0].shape.HeightField.0 = { columns: 5, rows: 3, smooth: true }
// model: objects[0].shape.HeightField.0.heights.len = 15
// model: objects[0].shape.HeightField.0.heights[0] = 0.5
// model: objects[0].shape.HeightField.0.heights[1] = 0
// model: objects[0].shape.HeightField.0.heights[3] = 1
// model: objects[0].shape.HeightField.0.heights[4] = 0.5
