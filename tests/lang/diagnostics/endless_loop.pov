#while (1) #end
// error: 1:1 too many loop iterations (more than 10000000); is this loop endless?
