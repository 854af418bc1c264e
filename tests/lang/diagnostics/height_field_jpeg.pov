height_field { "hills.jpg" }
// error: 1:16 unsupported: `other images in a height_field` is not supported yet
