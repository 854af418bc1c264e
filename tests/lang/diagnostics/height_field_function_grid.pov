height_field { function 1, 20 { x * y } }
// error: 1:25 a function height field needs 2 to 8192 points each way, found 1 x 20
