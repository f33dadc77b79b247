#version 450 core
// inject_geometry per geometry-volume cell (shaders/shared/lpv/inject_geometry_kernel.h). uMode
// 0: the blocking potential from voxelize's weight and normal sums; with inject_geometry.blockers=rsm,
// 1: keep the scattered light's sum (lpv/inject_geometry_rsm.comp) where its area is the larger,
// 2: the blocking potential from the kept sums.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

uniform int uResolution;
uniform int uMode;
layout(std430, binding = 0) readonly buffer Weights { uint weights[]; };
layout(std430, binding = 1) readonly buffer Normals { int normals[]; };
layout(std430, binding = 2) writeonly buffer Blocking { vec4 blocking[]; };
layout(std430, binding = 3) readonly buffer Scratch { ivec4 scratch[]; };
layout(std430, binding = 4) buffer Sums { ivec4 sums[]; };

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
  int e = g.x + n * (g.y + n * g.z);
  if (uMode == 0) {
    blocking[e] = cornerBlocking(g);
  } else if (uMode == 1) {
    if (scratch[e].x > sums[e].x) sums[e] = scratch[e];
  } else {
    blocking[e] = rsmBlocking(vec4(sums[e]));
  }
}
