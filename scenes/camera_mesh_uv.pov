// The mesh camera, distribution 3 with smooth: a uv-mapped grid of 8 x 6 cells whose interpolated corner normals fan out like a perspective lens; pixels whose (u, v) falls outside the map (a margin all round) are black (src/render/mesh_camera.rs).
#version 3.7;
#declare N = 8;
#declare M = 6;
#macro Corner(I, J) <(I / N - 0.5) * 4 / 3, J / M - 0.5, 0> #end
#macro Uv(I, J) <0.05 + 0.9 * I / N, 0.05 + 0.9 * J / M> #end
#macro Lens(I, J) vnormalize(Corner(I, J) * 0.8 + z) #end
#declare Lens_Mesh = mesh {
  #for (J, 0, M - 1)
    #for (I, 0, N - 1)
      // Corners a, b, c with (c - a) x (b - a) along +z: the rays go into the scene.
      smooth_triangle { Corner(I, J), Lens(I, J), Corner(I, J + 1), Lens(I, J + 1),
        Corner(I + 1, J), Lens(I + 1, J) uv_vectors Uv(I, J), Uv(I, J + 1), Uv(I + 1, J) }
      smooth_triangle { Corner(I + 1, J + 1), Lens(I + 1, J + 1), Corner(I + 1, J), Lens(I + 1, J),
        Corner(I, J + 1), Lens(I, J + 1) uv_vectors Uv(I + 1, J + 1), Uv(I + 1, J), Uv(I, J + 1) }
    #end
  #end
}
camera {
  mesh_camera { 1 3 mesh { Lens_Mesh rotate x * -10 translate <0, 0.4, -0.5> } smooth }
  location <0, 0, 0.01>
}
#include "data/camera_ring.inc"
