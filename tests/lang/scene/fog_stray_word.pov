fog { distance 10 color rgb 1 sphere }
// error: 1:31 expected `}` to close the fog, found `sphere`
