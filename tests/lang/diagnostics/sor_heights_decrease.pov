sor { 4, <0,0>, <1,1>, <0.5,0.5>, <1,3> }
// error: 1:7 the sor's heights must increase, but point 3 is at 0.5 after 1
