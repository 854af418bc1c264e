difference { sphere { 0, 1 } }
// warning: 1:14 the difference should have at least 2 objects
