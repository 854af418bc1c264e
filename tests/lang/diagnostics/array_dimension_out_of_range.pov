#declare A = array[3];
#declare N = dimension_size(A, 2);
// error: 2:32 this array has 1 dimensions, asked for dimension 2
