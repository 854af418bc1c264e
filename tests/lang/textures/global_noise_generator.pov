global_settings { noise_generator 3 }
plane { z, 0 pigment { bozo } }
plane { z, 0 pigment { bozo noise_generator 1 } }
// model: objects[0].texture.pigment.kind.ColourMap.pattern.noise_generator = 3
// model: objects[1].texture.pigment.kind.ColourMap.pattern.noise_generator = 1
