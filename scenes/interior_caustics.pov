// Interior caustics: POV-Ray's fake caustics brighten the light that shadow rays bring
// through a transparent object, by 1 + |cos|^(45 caustics) at each surface they cross. A
// glass sphere with caustics 1 casts a bright core inside its shadow; a tilted clear slab
// (ior 1) with caustics 0.3 brightens its shadow where the light meets it near its normal;
// a pale sphere without caustics keeps a plain filtered shadow.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera {
  location <0, 4.5, -5.5>
  look_at <0, 0.4, 0>
  right x*image_width/image_height
  angle 45
}
light_source { <1, 9, -1> color rgb 1 }
background { color rgb <0.2, 0.25, 0.3> }

plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.05 diffuse 0.8 } }
sphere {
  <-1.3, 1.1, 0.3>, 0.8
  pigment { color rgbf <0.9, 1, 0.9, 0.9> }
  finish { ambient 0 diffuse 0.05 phong 0.5 }
  interior { ior 1.45 caustics 1.0 }
}
box {
  <-0.7, -0.05, -0.7>, <0.7, 0.05, 0.7>
  pigment { color rgbf <1, 0.95, 0.85, 0.95> }
  finish { ambient 0 diffuse 0 }
  interior { caustics 0.3 }
  rotate z*-20
  translate <1.1, 1.4, 0.2>
}
sphere {
  <0.6, 0.45, -1.2>, 0.45
  pigment { color rgbf <1, 0.9, 0.8, 0.7> }
  finish { ambient 0 diffuse 0.2 }
  interior { ior 1.0 }
}
