camera { location <0,0,-1> look_at <1,0,-1> angle 90 }
// Looking along +x: the direction turns, its length set by the 90 degree angle.
// model: camera.direction = <0.665, 0, 0>
// model: camera.right = <0, 0, -1.33>
