julia_fractal { <0, 0, 0, 0> quaternion exp }
// error: 1:45 a quaternion julia_fractal takes only `sqr` or `cube`
