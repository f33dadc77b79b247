#version 450 core
// inject_geometry: the shared kernel (shaders/shared/lpv/inject_geometry_kernel.h) per
// geometry-volume cell, reading voxelize's weight and normal sums.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(location = 0) uniform int uResolution;
layout(std430, binding = 0) readonly buffer Weights { uint weights[]; };
layout(std430, binding = 1) readonly buffer Normals { int normals[]; };
layout(std430, binding = 2) writeonly buffer Blocking { vec4 blocking[]; };

vec4 surfaceAt(ivec3 v) {
  int n = uResolution;
  if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, ivec3(n)))) return vec4(0.0f);
  int e = v.x + n * (v.y + n * v.z);
  return vec4(float(weights[e]), float(normals[3 * e]), float(normals[3 * e + 1]),
              float(normals[3 * e + 2]));
}

#include "shared/lpv/inject_geometry_kernel.h"

void main() {
  ivec3 g = ivec3(gl_GlobalInvocationID);
  int n = uResolution;
  if (any(greaterThanEqual(g, ivec3(n)))) return;
  blocking[g.x + n * (g.y + n * g.z)] = cornerBlocking(g);
}
