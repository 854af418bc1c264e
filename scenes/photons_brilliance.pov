// Photons on walls and a floor of brilliance 0.6: a glass slab standing in a round room,
// sunk a little into the floor and lit from low down (18 degrees), throws its light into
// its own shadow on the floor, where only photons reach. POV-Ray shades each photon as a
// light from its direction, so brilliance weighs it by cos^(b - 1) of its incidence
// (docs/differences.md, "Photons"): without that weight sqrt(B) is 0.021 (189/900 tiles
// fail), with it 0.0019 (0/900).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 25 photons { spacing 0.01 autostop 0 jitter 0 } }
camera { location <20, 4.6, 10> right x*image_width/image_height look_at <0, 2.4, 0> angle 38 }
light_source { <-10, 7, 18> color rgb <0.65, 0.6, 0.55> fade_power 2 fade_distance 45
  photons { reflection on refraction on } }
cylinder { 0, 9*y, 30 hollow on pigment { rgb 1 } finish { ambient 0 diffuse 0.7 brilliance 0.6 } }
box { <-3, -0.05, -0.6>, <3, 2.4, 0.6>
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0.1 specular 0.6 roughness 0.002 brilliance 5
    reflection { 0.1, 1 fresnel on } conserve_energy }
  interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color rgb <0.35, 0.65, 0.85> }
  photons { target reflection on refraction on } }
