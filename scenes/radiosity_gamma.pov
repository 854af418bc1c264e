// Radiosity in a scene computed in gamma space (assumed_gamma 2.2, as in POV-Ray 3.6-era
// scenes): a closed white room with a red and a blue block, lit by one fading light.
// POV-Ray decodes each traced value, and its radiosity comes from a smooth cache; penumbra
// averages 16 radiosity rays at a camera path's first bounce before decoding, so that the
// decoding curve does not turn its noise into brightness (src/render/integrator/radiosity.rs).
// The reference is POV-Ray at count 300, error_bound 0.2, nearest_count 10.
#version 3.7;
global_settings {
  assumed_gamma 2.2
  radiosity {
    count 300 error_bound 0.2 nearest_count 10 pretrace_start 0.08 pretrace_end 0.01
    low_error_factor 0.5 minimum_reuse 0.01
    recursion_limit 2
  }
}
camera { location <-2, 2.5, -9> look_at <0.5, 0.8, 0> right x*image_width/image_height angle 50 }
light_source { <1, 4.5, -2> color rgb 0.6 fade_distance 6 fade_power 2 }

// The room: the inside of a white box.
box { <-5, 0, -10>, <5, 5, 5> pigment { rgb 1 } finish { ambient 0 diffuse 0.8 } inverse }
box { <-2.5, 0, -0.5>, <-0.5, 2.5, 1.5> pigment { rgb <0.9, 0.15, 0.1> } finish { ambient 0 diffuse 0.8 } }
box { <0.8, 0, -1.5>, <2.4, 1.2, 0.1> pigment { rgb <0.1, 0.2, 0.9> } finish { ambient 0 diffuse 0.8 } rotate y*20 }
