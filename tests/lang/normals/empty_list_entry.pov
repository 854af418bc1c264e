plane { y, 0 normal { checker normal { ripples } normal { } } }
// error: 1:50 a list pattern's normal entry needs a pattern (POV-Ray: "No normal type")
