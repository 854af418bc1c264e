prism { linear_spline 0, 1, 5, <0,0>, <1,0>, <1,1>, <0,0>
  pigment { rgb 1 } }
// error: 1:29 the prism declares 5 points but gives 4
