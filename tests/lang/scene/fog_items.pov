// Every fog item, POV-Ray's defaults, and a declared fog reused and changed.
#declare Mist = fog { fog_type 2 distance 50 color rgbft <0.8, 0.9, 1, 0.3, 0.1>
  fog_offset 0.5 fog_alt 2 up <0, 2, 0> turbulence 0.8 octaves 3 omega 0.4 lambda 2.5
  turb_depth 0.3 translate <0, 1, 0> }
fog { Mist }
fog { Mist fog_type 1 }
fog { distance 10 color rgb 1 }
fog { Mist rotate 90*z }
// model: fogs.len = 4
// model: fogs[0].kind = Ground { offset: 0.5, alt: 2 }
// model: fogs[0].distance = 50
// model: fogs[0].colour = { rgb: <0.8, 0.9, 1>, filter: 0.3, transmit: 0.1 }
// model: fogs[0].up = <0, 1, 0>
// model: fogs[0].turbulence.turbulence = { amount: <0.8, 0.8, 0.8>, octaves: 3, omega: 0.4, lambda: 2.5 }
// model: fogs[0].turbulence.depth = 0.3
// model: fogs[0].transform maps <0, 0, 0> to <0, 1, 0>
// model: fogs[1].kind = Constant
// model: fogs[2].turbulence = None
// model: fogs[2].up = <0, 1, 0>
// The transforms turn the up direction (and only it, of the ground fog's heights).
// model: fogs[3].up = <-1, 0, 0> within 1e-12
