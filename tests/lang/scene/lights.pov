light_source { <1,2,3>, color rgb <1,0.5,0.25> translate <1,0,0> }
light_source { <0,10,0> rgb 1 spotlight point_at <0,0,0> radius 10 falloff 20 tightness 5 }
light_source { <0,10,0> 1 area_light <1,0,0>, <0,0,1>, 5, 3 adaptive 1 jitter circular orient
  fade_distance 2 fade_power 2 shadowless area_illumination on }
light_source { <0,10,0> 1 parallel point_at <0,0,1> translate y }
// model: lights.len = 4
// model: lights[0].location = <2, 2, 3>
// model: lights[0].colour = <1, 0.5, 0.25>
// model: lights[1].kind = Spot { point_at: <0, 0, 0>, radius: 10, falloff: 20, tightness: 5 }
// model: lights[2].area = Some({ size1: 5, size2: 3, adaptive: Some(1), jitter: true, circular: true, orient: true })
// model: lights[2] = { shadowless: true, area_illumination: true, fade_distance: 2, fade_power: 2 }
// model: lights[3].kind = Parallel { point_at: <0, 1, 1> }
// model: lights[3].location = <0, 11, 0>
