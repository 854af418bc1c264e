prism { 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,0>, <5,5> }
// error: 1:46 more points than the 4 the prism declares
