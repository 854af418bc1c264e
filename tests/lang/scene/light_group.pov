#declare G = light_group {
  sphere { 0, 1 }
  light_source { <1, 2, 3> rgb 1 }
  global_lights
  translate x
}
light_source { <0, 9, 0> rgb 1 }
object { G }
light_group { box { -1, 1 } light_source { 0, rgb 1 } }
// model: lights.len = 3
// model: lights[0].group = None
// model: lights[1].location = <2, 2, 3>
// model: lights[1].group = Some(0)
// model: lights[2].group = Some(1)
// model: objects[0].flags.light_group = Some(LightGroup { id: 0, global_lights: true })
// model: objects[1].flags.light_group = Some(LightGroup { id: 1, global_lights: false })
