// Every keyword of the radiosity block; a second block changes only what it names.
#version 3.7;
global_settings {
  radiosity { count 60, 1600 nearest_count 9, 3 error_bound 0.5 recursion_limit 3
    brightness 0.8 gray_threshold 0.2 low_error_factor 0.6 minimum_reuse 0.01
    maximum_reuse 0.1 pretrace_start 0.1 pretrace_end 0.005 adc_bailout 0.002
    normal on media on always_sample off max_sample 2 subsurface off }
  radiosity { brightness 1.2 }
}
sphere { 0, 1 finish { diffuse albedo 0.6 brilliance 3 } }
// model: settings.radiosity.recursion_limit = 3
// model: settings.radiosity.brightness = 1.2
// model: settings.radiosity.gray_threshold = 0.2
// model: settings.radiosity.normal = true
// model: settings.radiosity.media = true
// model: settings.radiosity.cache = { count: 60, directions: 1600, nearest_count: 9, nearest_count_min: 3, error_bound: 0.5, low_error_factor: 0.6, minimum_reuse: 0.01, maximum_reuse: 0.1, pretrace_start: 0.1, pretrace_end: 0.005, adc_bailout: 0.002, always_sample: false, max_sample: 2, subsurface: false }
// model: objects[0].texture.finish = { diffuse: 1.2, radiosity_diffuse: 0.6 }
