// rainbow: two rings around the direction of a far light behind the camera, fog-like:
// colours with filter and transmit over a sky_sphere, the outer ring cut to an arc around
// up with a soft falloff, the inner one jittered; at distance 60 they also show faintly on
// the ground and the spheres in front
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2, -10>
  look_at <0, 4, 0>
  right x*image_width/image_height
  angle 80
}
light_source { <-20, 30, -40> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.5, 0.6, 0.8>] [1 rgb <0.1, 0.2, 0.5>] } } }
plane { y, 0 pigment { checker rgb 0.5 rgb 0.3 scale 2 } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-3, 1, 4>, 1 pigment { rgb <0.8, 0.3, 0.2> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <3, 1.5, 8>, 1.5 pigment { rgb <0.3, 0.7, 0.3> } finish { ambient 0.2 diffuse 0.7 } }

rainbow {
  angle 42 width 6 distance 60 direction <-0.1, -0.25, 1>
  arc_angle 150 falloff_angle 60 up <0.2, 1, 0>
  color_map {
    [0.0 rgbft <1, 0.5, 1, 1, 0.2>]
    [0.3 rgbft <0.2, 0.3, 1, 0.8, 0.3>]
    [0.6 rgbft <0.2, 1, 0.2, 0.6, 0.3>]
    [1.0 rgbft <1, 0.2, 0.2, 0.2, 0.6>]
  }
}
rainbow {
  angle 30 width 4 distance 60 direction <-0.1, -0.25, 1> jitter 0.05
  color_map {
    [0.0 rgbt <1, 0.2, 0.2, 0.5>]
    [0.5 rgbt <1, 1, 0.2, 0.4>]
    [1.0 rgbt <0.3, 0.3, 1, 0.6>]
  }
}
