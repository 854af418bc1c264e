#declare F = finish { ambient 0.2 diffuse albedo 0.5 brilliance 3 phong albedo 1 phong_size 9
  specular 0.3 roughness 0.01 metallic reflection { 0.1, 0.8 falloff 2 fresnel exponent 2 metallic 0.5 }
  conserve_energy emission rgb <1,2,3> }
sphere { 0, 1 finish { F reflection_exponent 3 } }
sphere { 0, 1 finish { reflection 0.5 specular albedo 1 roughness 0.5 } }
sphere { 0, 1 finish { reflection { 0.7 fresnel } } }
// model: objects[0].texture.finish = { ambient: <0.2, 0.2, 0.2>, emission: <1, 2, 3>, diffuse: 1, phong: 5, specular: 0.3, metallic: 1, conserve_energy: true }
// model: objects[0].texture.finish.reflection = { min: <0.1, 0.1, 0.1>, max: <0.8, 0.8, 0.8>, falloff: 2, fresnel: true, metallic: 0.5, exponent: 3 }
// model: objects[1].texture.finish.reflection.min = <0.5, 0.5, 0.5>
// specular albedo 1 with roughness 0.5 (exponent 2): (e + 2) / (4 (2 - 2^(-e/2))).
// model: objects[1].texture.finish.specular = 0.6666666666666666 within 1e-12
// model: objects[2].texture.finish.reflection.min = <0, 0, 0>
// model: objects[2].texture.finish.reflection.max = <0.7, 0.7, 0.7>
