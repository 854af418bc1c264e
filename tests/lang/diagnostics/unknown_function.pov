// A name called like a function that is neither a built-in function, a macro nor a
// declared identifier: the error names it, and the hint the nearest built-in function.
// error: 6:14 unknown identifier `vlenght`
// hint: did you mean `vlength`?
#declare V = <1, 2, 3>;
#declare L = vlenght(V) * 2;
