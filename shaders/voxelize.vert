#version 450 core
// Conservative voxelization, vertex stage: no vertex attributes; vertex gl_VertexID is corner
// gl_VertexID % 3 of prepared triangle gl_VertexID / 3 (voxel-local coordinates).
#include "shared/voxelize_layout.h"

layout(std430, binding = 0) readonly buffer Triangles { VoxelTriangle triangles[]; };

void main() {
  VoxelTriangle t = triangles[gl_VertexID / 3];
  int corner = gl_VertexID % 3;
  gl_Position = vec4(corner == 0 ? t.v0.xyz : (corner == 1 ? t.v1.xyz : t.v2.xyz), 1.0f);
}
