// Expected values printed by POV-Ray 3.7.0.10 with `#debug str(rand(S), 0, 10)`.
#declare S0 = seed(0);
#declare A = rand(S0); #declare B = rand(S0); #declare C = rand(S0);
sphere { <A, B, C>, 1 }
#declare S1 = seed(12345);
#declare A = rand(S1); #declare B = rand(S1); #declare C = rand(S1);
sphere { <A, B, C>, 1 }
#declare S2 = seed(-7);
#declare A = rand(S2); #declare B = rand(S2); #declare C = rand(S2);
sphere { <A, B, C>, 1 }
#declare S3 = seed(2.7);
#declare A = rand(S3); #declare B = rand(S3); #declare C = rand(S3);
sphere { <A, B, C>, 1 }
#declare S4 = seed(4000000000);
#declare A = rand(S4); #declare B = rand(S4); #declare C = rand(S4);
sphere { <A, B, C>, 1 }
// model: objects[0].shape.center = <0.0000028743, 0.4665636845, 0.2490702288> within 6e-11
// model: objects[1].shape.center = <0.4665636845, 0.2490702288, 0.9658760421> within 6e-11
// model: objects[2].shape.center = <0.0460728682, 0.3226610886, 0.3312883220> within 6e-11
// model: objects[3].shape.center = <0.8439828762, 0.5076787119, 0.0827222022> within 6e-11
// model: objects[4].shape.center = <0.5000028744, 0.9665636846, 0.7490702290> within 6e-11
