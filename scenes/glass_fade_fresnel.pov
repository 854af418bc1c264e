// Fading glass with Fresnel reflection inside a closed room: a long bar seen end-on and a
// right-angle prism, both `reflection { 0.1, 1 fresnel on } conserve_energy` with an
// exponential fade. Rays inside them reflect totally along the walls and leave at angles
// near the critical one, where POV-Ray's fresnel gives a ray leaving the glass its minimum
// reflection (not the Fresnel equations' inner reflectance) and fades a total reflection
// because the room holds the glass (docs/differences.md, "Interiors")
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 25 }

camera {
  location <20, 4.6, 10>
  right x*image_width/image_height
  look_at <0, 2.4, 0>
  angle 38
}
light_source { <-10, 7, 18> color rgb <1.3, 1.2, 1.1> }

// The room: a closed hollow cylinder holding the camera, the light and the glass.
cylinder { 0*y, 9*y, 30
  texture { pigment { color rgb <0.98, 0.96, 0.90> } finish { diffuse 0.7 } }
  hollow on }

#declare Glass = material {
  texture {
    pigment { color rgbf <1, 1, 1, 1> }
    finish { specular 0.6 roughness 0.002 ambient 0 diffuse 0.1 brilliance 5
      reflection { 0.1, 1.0 fresnel on } conserve_energy }
  }
  interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color rgb <0.35, 0.65, 0.85> }
}

box { <-3, 0.001, -0.6>, <3, 2.4, 0.6> material { Glass } translate z*-1.5 }

intersection {
  box { <-1, 0, -1>, <1, 2, 1> }
  plane { <-1, 1, 0>, 0 }
  material { Glass }
  scale 1.6
  rotate y*-30
  translate <0.5, 0.001, 2.2>
}
