// noise patterns (compared with POV-Ray in distribution only, tests/appearance_noise.rs): bozo, granite, marble and wood with turbulence, agate, wrinkles
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -9> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-5, 5, -10> color rgb 1 }
#declare F = finish { ambient 0.3 diffuse 0.7 }
sphere { <-2.4, 1.2, 0>, 1.1 pigment { bozo color_map { [0 rgb <0.1,0.2,0.5>] [1 rgb <1,0.9,0.6>] } scale 0.5 } finish { F } }
sphere { <0, 1.2, 0>, 1.1 pigment { granite color_map { [0 rgb 0.1] [1 rgb <1,0.8,0.7>] } } finish { F } }
sphere { <2.4, 1.2, 0>, 1.1 pigment { marble turbulence 0.8 color_map { [0 rgb <0.9,0.9,0.85>] [0.8 rgb <0.6,0.55,0.5>] [1 rgb 0.1] } scale 0.8 } finish { F } }
sphere { <-2.4, -1.2, 0>, 1.1 pigment { wood turbulence 0.05 color_map { [0 rgb <0.6,0.35,0.1>] [1 rgb <0.9,0.7,0.4>] } scale 0.2 rotate x*70 } finish { F } }
sphere { <0, -1.2, 0>, 1.1 pigment { agate color_map { [0 rgb <0.4,0.1,0.05>] [1 rgb <1,0.9,0.7>] } scale 0.8 } finish { F } }
sphere { <2.4, -1.2, 0>, 1.1 pigment { gradient y warp { turbulence 0.6 } color_map { [0 rgb <0.1,0.4,0.2>] [0.5 rgb 1] [1 rgb <0.1,0.4,0.2>] } scale 0.7 } finish { F } }
