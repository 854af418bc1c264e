#version 3.6;
global_settings { assumed_gamma 1.0 max_trace_level 10 adc_bailout 0 ambient_light rgb <1,0.5,0.5> }
background { rgb <0.1, 0.2, 0.3> }
// model: version = 3.6
// (so the scene is legacy: Scene::legacy is version < 3.7)
// model: settings = { assumed_gamma: Some(1), max_trace_level: 10, adc_bailout: 0, ambient_light: <1, 0.5, 0.5> }
// model: background.rgb = <0.1, 0.2, 0.3>
