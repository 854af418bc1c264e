// warps: repeat (offset, flip), black_hole (falloff, strength, inverse, repeat), planar,
// cylindrical, spherical, toroidal (major_radius, dist_exp, orientation) and cubic
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 8*x up 6*y }

#declare Map = color_map { [0 rgb <0.9,0.2,0.1>] [0.5 rgb <0.95,0.9,0.3>] [1 rgb <0.1,0.3,0.8>] }
#declare F = finish { ambient 1 diffuse 0 }
#macro Panel(X, Y, P)
  box { <-1.2, -1.2, 0>, <1.2, 1.2, 0.1> pigment { P } finish { F } translate <X, Y, 0> }
#end

Panel(-2.7, 1.5, pigment { checker rgb 1, rgb <0.2,0.3,0.7> scale 0.25
  warp { repeat x*0.6 offset <0, 0.13, 0> flip y } rotate z*10 })
Panel(0, 1.5, pigment { gradient x color_map { Map } scale 0.5
  warp { black_hole <0.3, 0.2, 0>, 0.9 falloff 3 strength 1.5 } })
Panel(2.7, 1.5, pigment { checker rgb 1, rgb <0.7,0.2,0.2> scale 0.2
  warp { black_hole <0, 0, 0>, 0.3 strength 0.8 inverse repeat <0.8, 0.8, 0> } })
Panel(-2.7, -1.5, pigment { onion color_map { Map } scale 0.4
  warp { cylindrical dist_exp 0.5 } rotate x*-60 })
Panel(0, -1.5, pigment { gradient y color_map { Map } frequency 3
  warp { spherical orientation <0.3, 1, 0.2> } rotate <30, 20, 0> })
Panel(2.7, -1.5, pigment { checker rgb 1, rgb <0.2,0.6,0.3> scale 0.1
  warp { toroidal major_radius 0.7 dist_exp 1 } rotate x*-70 })
box { <-1.35, -0.3, 0>, <1.35, 0.3, 0.1> pigment { checker rgb 0.1, rgb 0.9 scale 0.05
  warp { cubic } translate <0.3, 0.2, -0.9> } finish { F } }
box { <-4, -0.3, 0>, <-1.5, 0.3, 0.1> pigment { gradient x color_map { Map } scale 0.3
  warp { planar <0.2, 1, 0.4>, 0.3 } rotate z*20 } finish { F } }
box { <1.5, -0.3, 0>, <4, 0.3, 0.1> pigment { gradient z color_map { Map } scale 0.2
  warp { planar } } finish { F } }
