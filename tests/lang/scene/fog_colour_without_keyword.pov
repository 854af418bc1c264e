// A colour identifier or expression stands for the fog's colour without `color`, as POV-Ray
// reads lights/circular.pov's `fog { distance 200 Wheat*.5 }`.
#declare Wheat = rgb <0.96, 0.87, 0.7>;
fog { distance 200 Wheat * 0.5 }
fog { Wheat + rgb 0.04 distance 700 }
// model: fogs.len = 2
// model: fogs[0].colour = { rgb: <0.48, 0.435, 0.35>, filter: 0, transmit: 0 }
// model: fogs[1].distance = 700
// model: fogs[1].colour = { rgb: <1, 0.91, 0.74>, filter: 0, transmit: 0 }
