#version 3.7;
cone { <0,1,0>, 1, <0,1,0>, 0 }
// error: 2:1 degenerate cone: the base point equals the cap point
