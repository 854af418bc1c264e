// Transparency and refraction: a glass sphere (ior 1.5, Fresnel reflection, conserve_energy)
// and a transmitting box that casts a shadow, over a checkered floor. The box floats just
// above the floor: coincident transparent faces are ambiguous in POV-Ray and penumbra alike.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 2.2, -5>
  look_at <0, 0.8, 0>
  right x*image_width/image_height
  angle 45
}
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb <0.3, 0.35, 0.45> }

plane {
  y, 0
  pigment { checker color rgb 0.85 color rgb <0.2, 0.25, 0.3> }
}
sphere {
  <-0.7, 1, 0>, 1
  pigment { color rgbf <0.95, 0.95, 1, 0.9> }
  finish { ambient 0 diffuse 0.1 phong 0.8 phong_size 120 reflection { 0, 1 fresnel } conserve_energy }
  interior { ior 1.5 }
}
box {
  <0.6, 0.01, -0.5>, <1.6, 1.2, 0.5>
  pigment { color rgbt <0.9, 0.3, 0.2, 0.5> }
  finish { ambient 0.1 diffuse 0.5 }
  rotate y*-20
}
