// mandel, julia and magnet side by side: mandel with its own default colour map, with
// exponent 3 and interior / exterior types; julia with exponent 4 and a colour map; magnet
// 1 and 2 in their mandel and julia forms; a fractal normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 0, -10>
  look_at <0, 0, 0>
  right x*image_width/image_height
  angle 40
}
light_source { <-6, 8, -12> color rgb 1 }

#declare Fin = finish { ambient 0.6 diffuse 0.4 }
// Top row: mandel default map; mandel exponent 3 interior 1 exterior 6; julia exponent 4.
box { <-1, -1, 0>, <1, 1, 0.1>
    pigment { mandel 60 scale 0.9 translate x*0.6 } finish { Fin } translate <-2.4, 1.15, 0> }
box { <-1, -1, 0>, <1, 1, 0.1>
    pigment { mandel 40 exponent 3 interior 1, 2 exterior 6, 0.3
    color_map { [0 rgb <0.1,0,0.2>] [0.5 rgb <1,0.6,0.2>] [1 rgb <1,1,0.8>] } scale 0.8 }
  finish { Fin } translate <0, 1.15, 0> }
box { <-1, -1, 0>, <1, 1, 0.1>
    pigment { julia <-0.5, 0.5>, 30 exponent 4 interior 5, 2 exterior 2, 0.5
    color_map { [0 rgb <0,0.2,0.4>] [1 rgb <1,0.9,0.5>] } scale 0.75 }
  finish { Fin } translate <2.4, 1.15, 0> }
// Bottom row: magnet 1 mandel (interior 1), magnet 2 julia (exterior 3), and a plane lit
// with a julia normal.
box { <-1, -1, 0>, <1, 1, 0.1>
    pigment { magnet 1 mandel 40 interior 1, 3 exterior 1, 1
    color_map { [0 rgb <0.1,0.1,0.3>] [0.3 rgb <0.3,0.8,0.6>] [1 rgb 1] } scale 0.4 translate -x*0.4 }
  finish { Fin } translate <-2.4, -1.15, 0> }
box { <-1, -1, 0>, <1, 1, 0.1>
    pigment { magnet 2 julia <0.4, 0.3>, 30 exterior 3, 0.7 interior 4, 0.5 scale 0.35 translate -x*0.3 }
  finish { Fin } translate <0, -1.15, 0> }
box { <-1, -1, 0>, <1, 1, 0.1>
    pigment { rgb <0.9,0.8,0.7> }
  normal { julia <0.3, 0.44>, 30 0.6 interior 1, 1 scale 0.7 }
  finish { ambient 0.2 diffuse 0.8 } translate <2.4, -1.15, 0> }
