// slope_map and normal_map (measured): a slope map turns the pattern value into a height,
// a cubic Hermite curve per interval with slopes per unit of the interval, before the
// finite difference; a normal map mixes its entries' unit normals and ignores its own
// amount; ripples ignore a slope map; accuracy does not change the tilt
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3.2, -6>
  look_at <0, 0.6, 0>
  right x*image_width/image_height
  angle 55
}
light_source { <-4, 9, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.4 }

// Grooves with flat tops: zero slopes at both ends, a step in the middle of the map.
plane { y, 0 pigment { rgb <0.7, 0.75, 0.8> }
  normal { gradient x, 1.5 slope_map { [0 <0, 0>] [0.5 <1, 0>] [0.5 <1, -1>] [1 <0, 0>] } scale 0.7 }
  finish { ambient 0.1 diffuse 0.7 phong 0.4 phong_size 30 } }
// Onion rings with a sine wave, frequency and a three-entry map with slopes, coarser accuracy.
sphere { <-1.5, 1, 0.5>, 1 pigment { rgb <0.9, 0.5, 0.3> }
  normal { onion 2 frequency 2 sine_wave accuracy 0.05
    slope_map { [0 <0, 1>] [0.3 <0.6, 0>] [1 <1, 2>] } scale 0.6 translate <-1.5, 1, 0.5> }
  finish { ambient 0.1 diffuse 0.7 phong 0.3 } }
// A normal map of ripples, a slope-mapped gradient and plain leopard, mixed by a gradient;
// the outer amount is ignored, the outer rotation turns the entries too.
sphere { <1.4, 1, 0.3>, 1 pigment { rgb <0.5, 0.7, 0.9> }
  normal { gradient y, 0.3
    normal_map {
      [0.2 ripples 0.8 scale 0.3]
      [0.5 gradient x, 2 slope_map { [0 <0, 0>] [1 <1, 0>] } scale 0.25]
      [0.8 leopard 3 scale 0.08]
    }
    scale 2 rotate z*20 translate y*0.2 }
  finish { ambient 0.1 diffuse 0.7 phong 0.4 phong_size 50 } }
// A box with a normal map whose entries are bare normal bodies, one without any slope.
box { <-0.5, 0, -0.5>, <0.5, 0.8, 0.5> rotate y*30 translate <0, 0, -1.6>
  pigment { rgb <0.9, 0.85, 0.6> }
  normal { radial frequency 6
    normal_map { [0 waves 1 frequency 3] [0.5 gradient y, 0] [1 onion 1 scale 0.2 slope_map { [0 <0, 2>] [1 <1, -2>] }] } }
  finish { ambient 0.15 diffuse 0.6 } }
