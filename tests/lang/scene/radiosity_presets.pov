// The Radiosity_* presets come from the installed rad_def.inc through the include path.
#version 3.7;
#include "rad_def.inc"
global_settings { radiosity { Rad_Settings(Radiosity_Normal, on, off) } }
sphere { 0, 1 no_radiosity radiosity { importance 0.5 } }
// include-path: /usr/share/povray-3.7/include
// model: settings.radiosity.recursion_limit = 1
// model: settings.radiosity.brightness = 1.0
// model: settings.radiosity.normal = true
// model: settings.radiosity.media = false
// model: settings.radiosity.cache = { count: 200, nearest_count: 7, error_bound: 0.3, low_error_factor: 0.75, minimum_reuse: 0.017, pretrace_end: 0.01, adc_bailout: 0.005 }
// model: objects[0].flags = { no_radiosity: true }
