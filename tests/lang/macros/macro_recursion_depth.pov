#macro R(N) R(N+1) #end
R(0)
// error: 1:13 macro calls are nested too deeply (more than 256 levels)
