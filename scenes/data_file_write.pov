// A data file written with #fopen / #write and read back with #read: a spiral of spheres
// whose centres, radii and colours are computed once, written as POV-Ray writes them
// (comma-separated, vectors as <x,y,z>), then read back to build the scene. penumbra writes
// only with --allow-write DIR (the convergence test gives it a temporary folder).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.4, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -5> color rgb 0.3 }
plane { y, 0 pigment { checker color rgb 0.75 color rgb 0.55 } }
#declare Count = 9;
#fopen Out "spiral.txt" write
#for (I, 0, Count - 1)
  #declare A = I * 40;
  #declare R = 0.8 + 0.25 * I;
  #write (Out, <R * sin(radians(A)), 0.25 + 0.04 * I, R * cos(radians(A))>, ",",
          0.2 + 0.03 * I, ",", <0.3 + 0.07 * I, 0.8 - 0.06 * I, 0.5>, ",\n")
#end
#write (Out, "\"end\"\n")
#fclose Out
#fopen In "spiral.txt" read
#declare N = 0;
#while (defined(In))
  #read (In, Item)
  #if (defined(In))
    #switch (mod(N, 3))
      #case (0) #declare Centre = Item; #break
      #case (1) #declare Radius = Item; #break
      #case (2)
        sphere { Centre, Radius pigment { color rgb Item } finish { phong 0.4 } }
      #break
    #end
    #declare N = N + 1;
  #end
#end
