// Comparisons as POV-Ray 3.7's `#debug` prints them: `=`, `!=`, `<=` and `>=` within 1e-10,
// `<` and `>` strict.
#macro Want(Got, Expected, What) #if (Got != Expected) #error concat(What, ": got ", str(Got, 0, 0)) #end #end
#declare A = 0.1 + 0.2;
Want((A < 0.3), 0, "A < 0.3")
Want((A <= 0.3), 1, "A <= 0.3")
Want((A = 0.3), 1, "A = 0.3")
Want((A != 0.3), 0, "A != 0.3")
Want((A > 0.3), 1, "A > 0.3")
Want((A >= 0.3), 1, "A >= 0.3")
#declare C = 0.5 + 1e-12;
Want((C <= 0.5), 1, "C <= 0.5")
#declare E = 0.5 + 2e-10;
Want((E <= 0.5), 0, "E <= 0.5")
Want((E = 0.5), 0, "E = 0.5")
#declare G = 0.5 - 1e-12;
Want((G >= 0.5), 1, "G >= 0.5")
Want((G < 0.5), 1, "G < 0.5")
// The loop animations/quilted/plotqlt.pov draws its curve with: 101 steps, not 100.
#declare X = -0.5;
#declare N = 0;
#while (X <= 0.5)
  #declare N = N + 1;
  #declare X = X + 0.01;
#end
Want(N, 101, "steps")
sphere { 0, 1 }
// model: objects.len = 1
