#declare N = 3;
#if (N > 2) #error concat("too many: ", str(N, 0, 0)) #end
// error: 2:13 #error: too many: 3
