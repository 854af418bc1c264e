#macro Ball(P, R) sphere { P, R } #end
#macro Twice(V) (V * 2) #end
#macro Inc(N) #declare N = N + 1; #end
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#declare K = 1; Inc(K) Inc(K)
Ball(<1,0,0>, Twice(3))
Ball(0, K)
sphere { 0, Fact(5) }
// model: objects.len = 3
// model: objects[0].shape.radius = 6
// model: objects[1].shape.radius = 3
// model: objects[2].shape.radius = 120
// value: K = 3
