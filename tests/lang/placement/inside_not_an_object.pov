#declare P = inside(<1, 2, 3>, 0);
// error: 1:21 `inside` needs an object as its first argument, found a vector
