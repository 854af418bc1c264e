#declare A = 1 + 2 * 3 - -4 / 2;
#declare V = <1,2,3> * 2 + 1;
#declare L = vlength(<3,4,0>);
#declare M = max(1, 5, 3) + min(2, -1) + pow(2, 10) + abs(-2) + sqrt(16);
#declare C = vcross(x, y);
#declare D = vdot(<1,2,3>, <4,5,6>) + degrees(pi) + radians(180);
sphere { V, A pigment { rgb <L, M, D> } }
sphere { C, (2 < 3) + (3 = 3) + (1 & 0) + (1 | 0) + (0 ? 5 : 7) }
// model: objects[0].shape = Sphere { center: <3, 5, 7>, radius: 9 }
// model: objects[0].texture.pigment.kind.Solid.0.rgb = <5, 1034, 215.14159265358979>
// model: objects[1].shape = Sphere { center: <0, 0, 1>, radius: 10 }
// value: A = 9
// value: V = <3, 5, 7>
// value: M = 1034
