#declare F = function { x + Missing }
// error: 1:29 unknown identifier `Missing`
