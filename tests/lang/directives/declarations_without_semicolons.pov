#declare I = 0
#while (I < 3)
  sphere { <I, 0, 0>, 1 }
  #declare I = I + 1
#end
#declare C = rgb <1, 0, 0>
#declare D = C
#declare A = array[2]
#declare A[0] = 5
sphere { 0, A[0] pigment { D } }
// model: objects.len = 4
// model: objects[3].texture.pigment.kind = Solid({ rgb: <1, 0, 0>, filter: 0, transmit: 0 })
// value: I = 3
