// Flat objects inside a medium: a ray crossing a disc, polygon or triangle enters it from
// either side, as it enters a solid, unless it is inside it already (POV-Ray's rule). Behind
// a non-hollow one the medium stops (the left disc, facing up, and the polygon, facing down);
// behind a hollow one it goes on (the right disc, facing down). A slide over the box's
// middle, POV-Ray's palette test.png with entry 5 clear, casts shafts of light into the
// medium. The reference is rendered with --declare MediaIntervals=10
// --declare MediaSamples=10.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (MediaIntervals) #declare MediaIntervals = 1; #end
#ifndef (MediaSamples) #declare MediaSamples = 4; #end

camera { location <0, 2.5, -12> look_at <0, -0.4, 0> right x*image_width/image_height angle 36 }
light_source { <0, 6, 0> color rgb 1.5 spotlight point_at <0, 0, 0> radius 25 falloff 30 }
light_source { <-20, 30, -30> color rgb 0.3 shadowless media_interaction off }
plane { y, -1.5 pigment { checker color rgb 0.8 color rgb 0.3 scale 1 } }
box { <-3.5, -1.49, -1.5>, <3.5, 0.2, 1.5> hollow
  pigment { color rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { scattering { 1, 0.3 } absorption 0.1
    method 2 intervals MediaIntervals samples MediaSamples } } }
disc { <-2.4, 0, 0>, y, 0.9 pigment { color rgbt <1, 0.9, 0.8, 0.8> } }
disc { <2.4, 0, 0>, -y, 0.9 hollow pigment { color rgbt <0.8, 0.9, 1, 0.8> } }
polygon { 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  pigment { image_map { png "test.png" once transmit 5, 1 } translate <-0.5, -0.5, 0> }
  scale 1.3 rotate 90*x translate y*0.05
}
triangle { <-0.6, -0.6, -1.4>, <0.6, -0.6, -1.4>, <0, 0.1, -1.4> pigment { color rgbt <1, 1, 1, 0.7> } }
