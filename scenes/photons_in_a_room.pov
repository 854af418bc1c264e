// Photons through fading glass with Fresnel reflection, inside a room: a hollow sphere
// round the scene holds the light, the glass ball and the floor. Photons start inside
// what holds their light, so leaving the ball they pass into the room's interior, where
// POV-Ray's fresnel gives a ray leaving glass no reflection (docs/differences.md,
// "Interiors"); without the room both renderers draw a different caustic (POV-Ray's two
// images differ by up to 0.028), and penumbra followed the open-air rule in the room before
// photons knew where they start. The camera looks at the caustic beside the ball.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 photons { spacing 0.003 autostop 0 jitter 0 } }
camera { orthographic location <-2.3, 10, 0> direction -y right x*3.2 up z*2.4 look_at <-2.3, 0, 0> }
light_source { <4.5, 12, 0> color rgb 1 photons { reflection on refraction on } }
plane { y, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 1 } }
sphere { <0, 3, 0>, 1
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 1.5 fade_distance 0.5 fade_power 1001 fade_color rgb <0.3, 0.6, 0.9> }
  photons { target reflection on refraction on collect off } }
// The room.
sphere { 0, 50 hollow pigment { rgbf 1 } finish { ambient 0 diffuse 0 } }
