#declare S = spline { linear_spline }
// error: 1:21 a spline needs at least one `time, vector` entry
