// pavement's corner styles: exterior (cut 1, rounded 2) at convex corners, form (cut 1,
// rounded 2, 3 leaving the bend to the others) at the bends of squares and the 120-degree
// corners of triangles and hexagons, interior (1, 2) at reflex corners; every other slab
// also takes the pattern as its normal
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 9, -5.5>
  look_at <0, 0, -0.3>
  right x*image_width/image_height
  angle 48
}
light_source { <-3, 12, -6> color rgb 1 }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 3 exterior 1
      color_map { [0 rgb <0.8, 0.3, 0.2>] [0.55 rgb <0.8, 0.3, 0.2> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <-3, 0, 2> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 3 form 3 exterior 2 interior 2
      color_map { [0 rgb <0.2, 0.5, 0.8>] [0.55 rgb <0.2, 0.5, 0.8> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    normal { pavement 0.4 number_of_sides 4 number_of_tiles 5 pattern 3 form 3 exterior 2 interior 2 scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <-1, 0, 2> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 4 number_of_tiles 3 pattern 2 form 2
      color_map { [0 rgb <0.3, 0.7, 0.3>] [0.55 rgb <0.3, 0.7, 0.3> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <1, 0, 2> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 20 form 1 interior 1
      color_map { [0 rgb <0.7, 0.6, 0.2>] [0.55 rgb <0.7, 0.6, 0.2> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    normal { pavement 0.4 number_of_sides 4 number_of_tiles 6 pattern 20 form 1 interior 1 scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <3, 0, 2> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 7 exterior 2 form 2 interior 2
      color_map { [0 rgb <0.6, 0.3, 0.7>] [0.55 rgb <0.6, 0.3, 0.7> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <-3, 0, 0> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 4 exterior 1 form 1 interior 1
      color_map { [0 rgb <0.3, 0.6, 0.6>] [0.55 rgb <0.3, 0.6, 0.6> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    normal { pavement 0.4 number_of_sides 3 number_of_tiles 5 pattern 4 exterior 1 form 1 interior 1 scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <-1, 0, 0> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 7 form 2 interior 2
      color_map { [0 rgb <0.8, 0.5, 0.4>] [0.55 rgb <0.8, 0.5, 0.4> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <1, 0, 0> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 13 form 1 interior 1
      color_map { [0 rgb <0.4, 0.4, 0.8>] [0.55 rgb <0.4, 0.4, 0.8> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    normal { pavement 0.4 number_of_sides 6 number_of_tiles 5 pattern 13 form 1 interior 1 scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <3, 0, 0> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 3 number_of_tiles 4 pattern 2 exterior 2 form 1 interior 2
      color_map { [0 rgb <0.5, 0.7, 0.3>] [0.55 rgb <0.5, 0.7, 0.3> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <-3, 0, -2> }

box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
  texture {
    pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 exterior 1 interior 1
      color_map { [0 rgb <0.7, 0.4, 0.5>] [0.55 rgb <0.7, 0.4, 0.5> * 0.7] [0.55 rgb <0.95, 0.9, 0.8>] [1 rgb <0.6, 0.55, 0.5>] }
      scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    normal { pavement 0.4 number_of_sides 4 number_of_tiles 4 pattern 5 form 2 exterior 1 interior 1 scale 0.25 rotate y*15 translate <0.2, 0, 0.1> }
    finish { ambient 0.2 diffuse 0.7 specular 0.3 }
  }
  translate <-1, 0, -2> }
