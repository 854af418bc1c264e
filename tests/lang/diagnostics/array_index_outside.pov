#declare A = array[2];
#declare B = A[5];
// error: 2:16 index 5 is outside the array (size 2)
