#version 450 core
// Antialiased voxelization: the n*n area samples of every triangle are splatted with the trilinear
// tent kernel, in the order of shaders/shared/voxelize_kernel.h (antialiasedRowBarycentric) and the
// fixed point of cpu/voxelize.cpp. One invocation handles one
// row i of one triangle's subdivision (at most 2n - 1 samples): llvmpipe ends an invocation after
// 65535 loop iterations, which a whole large triangle (n^2 samples * 8 corners) would exceed.
layout(local_size_x = 64) in;
#include "shared/texture_layout.h"
#include "texture_access.glsl"
#include "shared/voxelize_surface.h"
#include "voxelize_accumulate.glsl"

// firstRow[t] = sum of the subdivisions n of triangles before t; firstRow[count] = all rows.
layout(std430, binding = 2) readonly buffer Rows { uint firstRow[]; };
uniform uint uTriangleCount;
uniform uint uRowCount;

void main() {
  uint row = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
  if (row >= uRowCount) return;
  uint lo = 0u;
  uint hi = uTriangleCount;
  while (hi - lo > 1u) {  // the triangle whose rows contain `row`
    uint mid = (lo + hi) / 2u;
    if (firstRow[mid] <= row) lo = mid;
    else hi = mid;
  }
  VoxelTriangle t = triangles[lo];
  int i = int(row - firstRow[lo]);
  for (int k = 0; k < antialiasedRowSamples(t, i); ++k) {
    vec2 b = antialiasedRowBarycentric(t, i, k);
    vec3 p = antialiasedSample(t, b);
    ivec3 base = tentBase(p);
    for (int corner = 0; corner < 8; ++corner) {
      ivec3 voxel = tentCorner(base, corner);
      bool inside = all(greaterThanEqual(voxel, ivec3(0))) && all(lessThan(voxel, ivec3(uResolution)));
      uint w = inside ? tentWeight(t, p, base, corner) : 0u;
      if (w != 0u) accumulate(voxel, surfaceContribution(t, w, b));
    }
  }
}
