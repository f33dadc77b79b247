#version 450 core
// Conservative voxelization, geometry stage ([Kahl 2019, §4.4.2] plus conservative expansion):
// project the triangle along its dominant axis onto the N x N viewport (one pixel = one voxel
// column) and push each edge outward by half a pixel's extent along the edge normal
// (Hasselgren et al., GPU Gems 2 ch. 42), so every column whose closed square the triangle's
// projection touches gets a fragment. The enlarged triangle overshoots at sharp corners; the
// fragment stage discards columns outside the triangle's column range.
#include "shared/voxelize_kernel.h"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

layout(std430, binding = 0) readonly buffer Triangles { VoxelTriangle triangles[]; };
uniform int uResolution;

flat out int gTriangle;
flat out ivec4 gColumns;  // inclusive column range (u0, w0, u1, w1), as cpu/voxelize.cpp

void main() {
  uint axis = triangles[gl_PrimitiveIDIn].dominantAxis;
  vec2 p[3];
  for (int i = 0; i < 3; ++i) p[i] = toDominant(gl_in[i].gl_Position.xyz, axis).xy;
  vec2 lo = min(p[0], min(p[1], p[2]));
  vec2 hi = max(p[0], max(p[1], p[2]));
  ivec4 columns = ivec4(ivec2(ceil(lo)) - 1, ivec2(floor(hi)));

  // Edge lines n_i . x = c_i, oriented outward, moved out by (0.5 + margin) * |n_i|_1.
  float orientation = sign((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x));
  vec2 n[3];
  float c[3];
  for (int i = 0; i < 3; ++i) {
    vec2 e = p[(i + 1) % 3] - p[i];
    n[i] = orientation * vec2(e.y, -e.x);
    c[i] = dot(n[i], p[i]) + (0.5f + 1.0f / 64.0f) * (abs(n[i].x) + abs(n[i].y));
  }
  float toNdc = 2.0f / float(uResolution);
  for (int i = 0; i < 3; ++i) {
    int j = (i + 2) % 3;  // the edge ending at vertex i
    float det = n[j].x * n[i].y - n[j].y * n[i].x;
    vec2 q = vec2(c[j] * n[i].y - c[i] * n[j].y, n[j].x * c[i] - n[i].x * c[j]) / det;
    gTriangle = gl_PrimitiveIDIn;
    gColumns = columns;
    gl_Position = vec4(q * toNdc - 1.0f, 0.0f, 1.0f);
    EmitVertex();
  }
  EndPrimitive();
}
