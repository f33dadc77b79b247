#version 450 core
// inject_geometry with inject_geometry.blockers=rsm: one invocation per texel of one light's views adds
// the surface it saw (shaders/shared/lpv/rsm_kernel.h) to its geometry-volume cell
// with integer atomics, so the sums do not depend on the order invocations run in.
layout(local_size_x = 64) in;
#include "shared/lpv/rsm_kernel.h"

uniform int uResolution;
uniform int uFirstView;
uniform int uViewCount;
layout(std430, binding = 0) readonly buffer Views {
  RsmParams rsm;
  RsmView views[];
};
layout(std430, binding = 1) readonly buffer Depth { float depths[]; };
layout(std430, binding = 2) readonly buffer Normal { float normals[]; };
layout(std430, binding = 3) buffer Scratch { int scratch[]; };

void main() {
  int r = rsm.resolution;
  int local = int(gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y);
  if (local >= r * r * uViewCount) return;
  int t = uFirstView * r * r + local;
  float depth = depths[t];
  if (depth == 0.0f) return;
  int row = local / r;
  vec3 n = vec3(normals[3 * t], normals[3 * t + 1], normals[3 * t + 2]);
  ivec3 cell;
  ivec4 q = rsmBlocker(views[uFirstView + row / r], ivec2(local - row * r, row % r), r, depth, n,
                       cell);
  int size = uResolution;
  if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, ivec3(size)))) return;
  int w = 4 * (cell.x + size * (cell.y + size * cell.z));
  for (int c = 0; c < 4; ++c)
    if (q[c] != 0) atomicAdd(scratch[w + c], q[c]);
}
