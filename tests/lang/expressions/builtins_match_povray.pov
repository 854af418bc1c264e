// Values checked against POV-Ray 3.7's own `#debug` output for the same expressions.
#macro Check(Got, Want) #if (vlength(Got - Want) > 1e-4) #error concat("got ", vstr(3, Got, ",", 0, 4)) #end #end
Check(vaxis_rotate(<1,0,0>, <0,1,0>, 90), <0,0,-1>)
Check(vrotate(<1,0,0>, <0,90,0>), <0,0,-1>)
Check(vaxis_rotate(<0,1,0>, <1,1,0>, 30), <0.0670,0.9330,0.3536>)
Check(vrotate(<0,1,0>, <30,20,10>), <0.0180,0.8826,0.4698>)
Check(<mod(-7, 3), div(-7, 2), int(-2.5)>, <-1, -3, -2>)
Check(log(100), 2)
#if (strcmp(str(3.14159, -8, 2), "00003.14") != 0) #error "str" #end
#if (strcmp(str(2, 5, -1), "2.000000") != 0) #error "str 2" #end
#if (strcmp(concat("a", chr(66), substr("xcdx", 2, 2)), "aBcd") != 0) #error "concat" #end
sphere { 0, 1 }
// model: objects.len = 1
