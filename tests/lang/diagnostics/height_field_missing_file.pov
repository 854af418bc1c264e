height_field { png "missing.png" smooth }
// error: 1:20 cannot find the height field image "missing.png"
