// Dispersion: a prism and a sphere of dispersing glass in front of sharp black and white
// stripes, so each edge seen through them fans out into POV-Ray's wavelengths. The prism
// (ior 1.5, dispersion 1.15, 7 samples by default) bends the stripes; the sphere (ior 1.4,
// dispersion 1.2, 3 samples, with a mirror reflection) disperses on the way in and keeps
// the wavelength on the way out; a second, clear prism behind it refracts a dispersed ray
// at its own single ior.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0, 1.2, -5>
  look_at <0, 1, 0>
  right x*image_width/image_height
  angle 40
}
light_source { <-3, 6, -6> color rgb 1 }
background { color rgb <0.05, 0.05, 0.08> }

// The stripes: emissive, so they are the same from every direction.
plane {
  z, 3
  pigment { gradient x color_map { [0.5 color rgb 1] [0.5 color rgb 0.02] } scale 0.35 }
  finish { ambient 0 diffuse 0 emission 1 }
}
plane { y, 0 pigment { color rgb 0.6 } finish { ambient 0 diffuse 0.7 } }

// A triangular prism, apex up, its edges along z.
intersection {
  plane { -y, 0 }
  plane { <-0.866, 0.5, 0>, 0.5 }
  plane { <0.866, 0.5, 0>, 0.5 }
  plane { z, 0.8 }
  plane { -z, 0.8 }
  translate <-0.9, 0.35, 0.5>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 dispersion 1.15 }
}
sphere {
  <0.9, 1.1, 0>, 0.75
  pigment { color rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0.05 phong 0.6 phong_size 80 reflection 0.08 }
  interior { ior 1.4 dispersion 1.2 dispersion_samples 3 }
}
box {
  <0.3, 0.2, 1.2>, <1.5, 2.2, 1.5>
  rotate y*25
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.3 }
}
