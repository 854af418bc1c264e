sphere { 0, 1 }
#fopen F "out.txt" write
// error: 2:1 unsupported: `#fopen` is refused: a scene may not open, read or write files
