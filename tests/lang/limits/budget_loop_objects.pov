// max-memory: 256K
#declare I = 0;
#while (I < 100000)
  sphere { <I, 0, 0>, 1 }
  #declare I = I + 1;
#end
// error: 3:1 the scene needs more than 256.0 KB (the memory budget): 513 objects made by the `#while` loop at limits/budget_loop_objects.pov:3:1
