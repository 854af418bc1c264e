// A data file read with #fopen / #read: twelve spheres (centre, radius, colour) from
// scenes/data/ring.txt, found beside the scene, until the closing "end" string.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -6.5> look_at <0, 0.3, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -5> color rgb 0.3 }
plane { y, 0 pigment { checker color rgb 0.75 color rgb 0.55 } }
#fopen Ring "data/ring.txt" read
#declare N = 0;
#declare Done = false;
#while (!Done)
  #read (Ring, Item)
  #if (defined(Ring) & !Done)
    #switch (mod(N, 3))
      #case (0) #declare Centre = Item; #break
      #case (1) #declare Radius = Item; #break
      #case (2)
        sphere { Centre, Radius pigment { color rgb Item } finish { phong 0.5 } }
      #break
    #end
    #declare N = N + 1;
  #end
  #if (!defined(Ring) | N > 100)
    #declare Done = true;
  #end
#end
#fclose Ring
// The file holds 12 x 3 values and a string; as in POV-Ray, the file closes as its last
// value (the string) is read, so N counts 36.
cylinder { <0, 0, 0>, <0, N / 20, 0>, 0.3 pigment { color rgb <0.9, 0.85, 0.3> } }
