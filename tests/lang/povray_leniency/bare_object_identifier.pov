#version 3.7;
// POV-Ray places a bare object identifier at the top level and takes one in looks_like
// (qtvr/qtvrpanorama.pov): measured, the same image as `object { S }`.
#declare S = sphere { <1, 2, 3>, 0.5 }
S
light_source { <0, 10, 0> color rgb 1 looks_like { S } }
// model: objects.len = 1
// model: objects[0].shape = Sphere { center: <1, 2, 3>, radius: 0.5 }
// model: lights[0].looks_like.shape.Sphere.radius = 0.5
