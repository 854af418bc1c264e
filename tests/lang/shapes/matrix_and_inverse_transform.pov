#declare T = transform { translate <1,2,3> scale 2 }
sphere { 0, 1 transform { T inverse } }
sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 4,5,6> }
// model: objects[0].transform maps <2, 4, 6> to <0, 0, 0>
// model: objects[1].transform maps <0, 0, 0> to <4, 5, 6>
