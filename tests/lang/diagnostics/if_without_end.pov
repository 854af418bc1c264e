#if (1)
sphere { 0, 1 }
// error: 1:1 this `#if` has no `#end`
