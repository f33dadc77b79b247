#version 450 core
// gbuffer for point clouds: each point's disc (shaders/shared/gbuffer_kernel.h, SurfaceDisc) as a
// square of two triangles in its plane, six vertices pulled by gl_VertexID; gbuffer_disc.frag
// cuts it to the circle. The square's half-side is twice the radius: the rasterizer snaps
// vertices to 1/256 pixel, and a square just around the circle could lose a pixel whose centre
// lies inside the circle next to the square's edge.
#include "shared/gbuffer_kernel.h"

layout(std430, binding = 3) readonly buffer Discs { SurfaceDisc discs[]; };
uniform mat4 uViewProjection;
flat out int vDisc;

void main() {
  vDisc = gl_VertexID / 6;
  SurfaceDisc d = discs[vDisc];
  // Corners (-1,-1) (1,-1) (1,1), (-1,-1) (1,1) (-1,1) of the square around the centre.
  const vec2 corners[6] = vec2[6](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1),
                                  vec2(-1, 1));
  vec2 c = corners[gl_VertexID % 6];
  vec3 n = d.normal.xyz;
  vec3 t = normalize(cross(n, abs(n.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0)));
  vec3 b = cross(n, t);
  vec3 p = d.center.xyz + 2.0f * d.radius * (c.x * t + c.y * b);
  gl_Position = uViewProjection * vec4(p, 1.0f);
}
