#declare V = <1, 2, 3>;
#declare F = function { x + V }
// error: 2:29 a function can use only floats, found a vector (use a component like `.x`)
