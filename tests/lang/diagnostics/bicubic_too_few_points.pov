bicubic_patch { type 1 u_steps 2 v_steps 2
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>
}
// error: 3:1 a bicubic_patch has 16 control points, found 4
