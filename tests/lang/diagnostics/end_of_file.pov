// error: 2:14 expected `}` to close the sphere, found end of file
sphere { 0, 1