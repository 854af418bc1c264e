sphere { 0, 1 }
#fopen F "out.txt" write
// error: 2:10 refused: writing "out.txt" needs --allow-write DIR (a folder the scene may write in)
