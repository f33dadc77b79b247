#version 450 core
// propagate: one gather step (shaders/shared/lpv/propagate_kernel.h) per cell, from the previous
// step's volume into the next, adding it to the accumulated volume; gpu/lpv/propagate.cpp
// dispatches it propagate.steps times, swapping the two step volumes.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#include "shared/lpv/storage.h"

layout(std430, binding = 0) readonly buffer Entries {
  PropagateParams params;
  PropagationEntry entries[];
};
layout(std430, binding = 1) readonly buffer Previous { float previous[]; };
layout(std430, binding = 2) writeonly buffer Next { float next[]; };
layout(std430, binding = 3) buffer Accumulated { float accumulated[]; };
layout(std430, binding = 4) readonly buffer Blocking { vec4 blocking[]; };
layout(location = 0) uniform int uOcclude;

int cellIndex(ivec3 v) {
  int n = params.resolution;
  return v.x + n * (v.y + n * v.z);
}
PropagationEntry entryAt(int e) { return entries[e]; }
int coefficientCount() { return params.coefficients; }
int colourCount() { return 3; }
float intensityAt(ivec3 cell, int word) {
  return previous[cellIndex(cell) * 3 * params.coefficients + word];
}
vec4 blockingAt(ivec3 g) {
  int n = params.resolution;
  if (any(lessThan(g, ivec3(0))) || any(greaterThanEqual(g, ivec3(n)))) return vec4(0.0f);
  return blocking[cellIndex(g)];
}
void storeIntensity(ivec3 cell, int word, float value) {
  int w = cellIndex(cell) * 3 * params.coefficients + word;
  next[w] = value;
  accumulated[w] = accumulatedValue(accumulated[w], value, params);
}

#include "shared/lpv/propagate_kernel.h"

void main() {
  ivec3 x = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(x, ivec3(params.resolution)))) return;
  PropagateParams p = params;
  p.occlude = uOcclude;
  propagateCell(x, p);
}
