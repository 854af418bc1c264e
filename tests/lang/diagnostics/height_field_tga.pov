height_field { "hills.tga" }
// error: 1:16 unsupported: `other images in a height_field` is not supported yet
