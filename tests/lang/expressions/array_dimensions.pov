#declare A = array[3][4];
#declare B = array[2] { 5, 6 }
sphere { <dimensions(A), dimension_size(A, 2), dimension_size(B, 1)>, B[1] }
// model: objects[0].shape = Sphere { center: <2, 4, 2>, radius: 6 }
