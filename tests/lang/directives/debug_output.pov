#declare N = 3;
#debug concat("N is ", str(N, 0, 1), "\n")
#debug "two\nlines\n"
// debug: N is 3.0
// debug: two
// debug: lines
// value: N = 3
