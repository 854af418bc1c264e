#declare A = array[3] { 1, 2, 3 };
#declare A[1] = 5;
#declare B = array[2][2] { {1, 2}, {3, 4} }
sphere { 0, A[1] + A[2] + B[1][0] }
// model: objects[0].shape = Sphere { center: <0, 0, 0>, radius: 11 }
