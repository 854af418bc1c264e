height_field { function 20, 20 { x * y } }
// error: 1:16 unsupported: `height_field { function ... }` is not supported yet
