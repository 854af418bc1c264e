// The mesh camera, distribution 0: one small triangle per pixel aimed like a perspective camera, two meshes a quarter pixel apart averaged, `location` moving the rays off the faces; the top row repeats the second, as POV-Ray's does (src/render/mesh_camera.rs).
#version 3.7;
#declare W = image_width;
#declare H = image_height;
// Face (i, j) of a mesh: a tiny triangle just in front of the eye whose normal (c - a) x
// (b - a) is the direction through pixel (i + Dx, j + Dy).
#macro PinholeMesh(Dx, Dy)
  mesh {
    #for (J, 0, H - 1)
      #for (I, 0, W - 1)
        #local D = vnormalize(<((I + Dx) / W - 0.5) * W / H, 0.5 - (J + Dy) / H, 1>);
        #local E1 = vnormalize(vcross(y, D));
        #local E2 = vcross(D, E1);
        #local P = D * 0.5;
        triangle { P, P + E2 * 0.001, P + E1 * 0.001 }
      #end
    #end
  }
#end
#declare Centres = PinholeMesh(0.5, 0.5)
#declare Shifted = PinholeMesh(0.75, 0.75)
camera {
  mesh_camera { 2 0
    mesh { Centres rotate x * -10 translate <0, 0.4, -0.5> }
    mesh { Shifted rotate x * -10 translate <0, 0.4, -0.5> }
  }
  location <0, 0, 0.05>
}
#include "data/camera_ring.inc"
