// max-memory: 1M
#declare Small = array[10];
#declare Big = array[1000][1000];
// error: 3:16 the scene needs more than 1.0 MB (the memory budget): an array of 1,000,000 elements at limits/budget_array.pov:3:16
