#macro R() R() #end R()
// error: 1:12 macro calls are nested too deeply (more than 256 levels)
