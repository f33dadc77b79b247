#version 450 core
// inject_lpv: one invocation per VPL adds its lobe (shaders/shared/lpv/inject_kernel.h) to its
// cell with integer atomics, so the sums do not depend on the order invocations run in.
layout(local_size_x = 64) in;
#include "shared/lpv/inject_kernel.h"

layout(std430, binding = 0) readonly buffer Vpls {
  InjectParams params;
  Vpl vpls[];
};
layout(std430, binding = 1) buffer Sums { int sums[]; };

void main() {
  // Two-dimensional dispatch: one dimension holds only 65535 groups.
  int v = int(gl_GlobalInvocationID.x + gl_NumWorkGroups.x * 64u * gl_GlobalInvocationID.y);
  if (v >= params.shape.z) return;
  Vpl vpl = vpls[v];
  int n = params.shape.x, coefficients = params.shape.y;
  ivec3 cell = vplCell(vpl);
  if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, ivec3(n)))) return;
  int first = (cell.x + n * (cell.y + n * cell.z)) * 3 * coefficients;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < coefficients; ++i) {
      int q = vplCoefficient(vpl, c, i, params.scale);
      if (q != 0) atomicAdd(sums[first + c * coefficients + i], q);
    }
}
