text { internal 1 "Hi" 1, 0 }
// error: 1:8 unsupported: `internal fonts` is not supported yet
