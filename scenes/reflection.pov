// Mirror reflection: three spheres with reflection, phong and specular highlights in front
// of a coloured back wall; reflections inside reflections test the trace depth.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

#declare Mirror = finish { ambient 0.05 diffuse 0.3 reflection 0.6 phong 0.8 phong_size 80 }

camera {
  location <0, 1.5, -5>
  look_at <0, 0.8, 0>
  right x*image_width/image_height
  angle 55
}
light_source { <-4, 6, -5> color rgb 1 }
light_source { <5, 3, -2> color rgb <0.3, 0.3, 0.4> }
background { color rgb <0.1, 0.15, 0.3> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } finish { reflection 0.2 } }
plane { z, 4 pigment { color rgb <0.8, 0.6, 0.3> } }
sphere { <-1.3, 1, 0>, 1 pigment { color rgb <0.9, 0.9, 0.95> } finish { Mirror } }
sphere { <1.1, 0.7, -0.6>, 0.7 pigment { color rgb <0.3, 0.9, 0.4> } finish { Mirror specular 0.6 roughness 0.02 } }
sphere { <0.3, 0.35, 1.2>, 0.35 pigment { color rgb <0.9, 0.2, 0.7> } finish { reflection { 0.1, 0.9 falloff 2 } } }
