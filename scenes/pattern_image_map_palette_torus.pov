// image_map's torus mapping (map_type 5: u around the y axis, v around a tube of major
// radius 1) on a torus, and a palette image's entries made transparent one by one
// (`transmit N, v`, `filter N, v`, after `transmit all`): POV-Ray's own 16-colour test.png,
// found through the include path, in front of a checkered wall
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.5, -6>
  look_at <0, 1, 0>
  right x*image_width/image_height
  angle 50
}
light_source { <-4, 9, -6> color rgb 1 }

plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 } finish { ambient 0.2 diffuse 0.7 } }
plane { z, 2 pigment { checker rgb <0.2, 0.4, 0.9> rgb <0.9, 0.8, 0.3> scale 0.4 }
  finish { ambient 0.3 diffuse 0.6 } }
torus { 1, 0.45
  pigment { image_map { png "images/test_card.png" map_type 5 interpolate 2 } }
  finish { ambient 0.15 diffuse 0.7 specular 0.3 }
  rotate x*-50 translate <-1.5, 1.2, 0>
}
box { <0, 0, 0>, <1, 1, 0.01>
  pigment { image_map { png "test.png" once transmit all 0.2 transmit 0, 1 transmit 1, 0.7
    filter 4, 0.8 } }
  finish { ambient 0.6 diffuse 0.4 }
  scale <2.4, 1.8, 1> rotate y*15 translate <0.4, 0.4, 0>
}
