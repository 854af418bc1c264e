// The means and standard deviations in src/function/tests.rs (FRACTAL_DISTRIBUTIONS),
// printed by POV-Ray 3.7 over the same 4000 points:
//   povray +Itests/povray_values/internal_fractal_distributions.pov -D +W1 +H1 +O/dev/null
#version 3.7;
#include "functions.inc"
#macro Stats(F, P0, P1, P2, P3, P4, P5, Name)
  #local S = 0; #local S2 = 0; #local K = 0;
  #while (K < 4000)
    #local X = mod(K * 0.8191725133961645, 1) * 40 - 20;
    #local Y = mod(K * 0.6710436067037893, 1) * 40 - 20;
    #local Z = mod(K * 0.5497004779019703, 1) * 40 - 20;
    #local V = F(X, Y, Z, P0, P1, P2, P3, P4, P5);
    #local S = S + V; #local S2 = S2 + V * V; #local K = K + 1;
  #end
  #local M = S / 4000;
  #debug concat(Name, " ", str(M, 0, 9), " ", str(sqrt(S2 / 4000 - M * M), 0, 9), "\n")
#end
#declare Noise = function(x, y, z, P0, P1, P2, P3, P4, P5) { f_noise_generator(x, y, z, P0) }
Stats(f_ridged_mf, 1.0, 2.0, 6.0, 1.0, 2.0, 2.0, "f_ridged_mf 59 [1.0, 2.0, 6, 1.0, 2.0, 2]")
Stats(f_ridged_mf, 0.5, 2.5, 4.0, 0.8, 1.5, 2.0, "f_ridged_mf 59 [0.5, 2.5, 4, 0.8, 1.5, 2]")
Stats(f_hetero_mf, 0.5, 2.0, 4.0, 0.7, 1.0, 2.0, "f_hetero_mf 29 [0.5, 2.0, 4, 0.7, 1, 2]")
Stats(f_hetero_mf, 0.8, 2.2, 6.0, 1.0, 0.0, 2.0, "f_hetero_mf 29 [0.8, 2.2, 6, 1.0, 0, 2]")
Stats(f_ridge, 2.0, 3.0, 0.5, 0.25, 1.0, 2.0, "f_ridge 58 [2.0, 3, 0.5, 0.25, 1.0, 2]")
Stats(f_ridge, 2.2, 5.0, 0.6, 0.0, 0.5, 2.0, "f_ridge 58 [2.2, 5, 0.6, 0.0, 0.5, 2]")
Stats(Noise, 2, 0, 0, 0, 0, 0, "f_noise_generator 78 [2]")
Stats(Noise, 3, 0, 0, 0, 0, 0, "f_noise_generator 78 [3]")
