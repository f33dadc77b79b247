#version 450 core
// inject: one invocation per VPL adds its lobe (shaders/shared/lpv/inject_kernel.h) to its
// cell with integer atomics, so the sums do not depend on the order invocations run in. uSource
// 0: the emitters' VPLs; 1: a VPL per RSM texel that saw a surface (shaders/shared/lpv/rsm_kernel.h).
layout(local_size_x = 64) in;
#include "shared/lpv/inject_kernel.h"
#include "shared/lpv/rsm_kernel.h"

uniform int uSource;
layout(std430, binding = 0) readonly buffer Vpls {
  InjectParams params;
  Vpl vpls[];
};
layout(std430, binding = 1) buffer Sums { int sums[]; };
layout(std430, binding = 2) readonly buffer Views {
  RsmParams rsm;
  RsmView views[];
};
// per texel, the rsm stage's buffers as they are: flux and normal rgb, depth
layout(std430, binding = 3) readonly buffer Flux { float flux[]; };
layout(std430, binding = 4) readonly buffer Normal { float normals[]; };
layout(std430, binding = 5) readonly buffer Depth { float depths[]; };

void main() {
  // Two-dimensional dispatch: one dimension holds only 65535 groups.
  int v = int(gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y);
  Vpl vpl;
  if (uSource == 0) {
    if (v >= params.vplCount) return;
    vpl = vpls[v];
  } else {
    int r = rsm.resolution;
    if (v >= r * r * rsm.viewCount) return;
    float depth = depths[v];
    if (depth == 0.0f) return;
    int row = v / r;
    vec3 n = vec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
    vec3 f = vec3(flux[3 * v], flux[3 * v + 1], flux[3 * v + 2]);
    vpl = rsmVpl(views[row / r], ivec2(v - row * r, row % r), r, depth, n, f, params.shiftRsmVpls == 1);
  }
  int n = params.resolution, coefficients = params.coefficients;
  ivec3 cell = vplCell(vpl);
  if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, ivec3(n)))) return;
  int first = (cell.x + n * (cell.y + n * cell.z)) * 3 * coefficients;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < coefficients; ++i) {
      int q = vplCoefficient(vpl, c, i, params.scale);
      if (q != 0) atomicAdd(sums[first + c * coefficients + i], q);
    }
}
