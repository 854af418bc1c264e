#version 3.7;

lathe { 0, y, 1 }
// error: 3:1 unsupported: `lathe` is not supported yet
