// vturbulence is the displacement the turbulence warp applies, with the same settings.
#declare P = <0.3, -1.7, 2.2>;
#declare V = vturbulence(2.5, 0.6, 4, P);
#declare Fx = function { pattern { function { x * 0.001 + 0.5 } warp { turbulence 1 octaves 4 omega 0.6 lambda 2.5 } } }
#declare Fy = function { pattern { function { y * 0.001 + 0.5 } warp { turbulence 1 octaves 4 omega 0.6 lambda 2.5 } } }
#declare Fz = function { pattern { function { z * 0.001 + 0.5 } warp { turbulence 1 octaves 4 omega 0.6 lambda 2.5 } } }
#declare W = <Fx(P.x, P.y, P.z), Fy(P.x, P.y, P.z), Fz(P.x, P.y, P.z)>;
#declare D = vlength((W - 0.5) / 0.001 - P - V);
#declare Moved = vlength(V) > 0.01;
// value: D = 0 within 1e-9
// value: Moved = 1
