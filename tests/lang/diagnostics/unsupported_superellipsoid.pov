#version 3.7;

superellipsoid { <1, 1> }
// error: 3:1 unsupported: `superellipsoid` is not supported yet
