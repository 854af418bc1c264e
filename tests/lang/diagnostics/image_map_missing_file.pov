// image: 16x16
sphere { 0, 1 pigment { image_map { png "missing.png" } } }
// error: 2:41 cannot find the image "missing.png"
