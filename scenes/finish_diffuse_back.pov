// Finish `diffuse front, back` (POV-Ray 3.7's backside illumination): a light behind a
// thin surface shines through the second value (times cos^brilliance and the opacity),
// one in front through the first; a double-illuminated panel is lit from behind through
// the first value instead. Three panels between the camera and a light behind them.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.4, -6>
  look_at <0, 1.1, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <1, 4, 5> color rgb 1.2 }
light_source { <-6, 5, -6> color rgb 0.3 }
background { color rgb <0.05, 0.05, 0.08> }

plane { y, 0 pigment { checker color rgb 0.6, color rgb 0.3 } }
// Paper.
polygon { 5, <-2.7, 0.2, 0>, <-1.0, 0.2, 0>, <-1.0, 2.2, 0>, <-2.7, 2.2, 0>, <-2.7, 0.2, 0>
  pigment { color rgb <1, 0.9, 0.7> } finish { diffuse 0.6, 0.4 } }
// A leaf: brilliance 2, and transmit 0.2, which scales both values by its opacity.
polygon { 5, <-0.85, 0.2, 0.3>, <0.85, 0.2, -0.3>, <0.85, 2.2, -0.3>, <-0.85, 2.2, 0.3>,
  <-0.85, 0.2, 0.3>
  pigment { color rgbt <0.5, 0.9, 0.4, 0.2> } finish { diffuse 0.5, 0.5 brilliance 2 } }
// Double-illuminated: the back value does not count.
polygon { 5, <1.0, 0.2, 0>, <2.7, 0.2, 0>, <2.7, 2.2, 0>, <1.0, 2.2, 0>, <1.0, 0.2, 0>
  pigment { color rgb <0.7, 0.8, 1> } finish { diffuse 0.6, 0.4 } double_illuminate }
