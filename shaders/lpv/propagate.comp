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
// The step volumes and the accumulated one: f32 words, or under lpv.storage=f16 two stored halves a
// word (storage.h, packStored), half the memory, as the thesis's RGBA16F volumes.
layout(std430, binding = 1) readonly buffer Previous { uint previous[]; };
layout(std430, binding = 2) buffer Next { uint next[]; };
layout(std430, binding = 3) buffer Accumulated { uint accumulated[]; };
layout(std430, binding = 4) readonly buffer Blocking { vec4 blocking[]; };
layout(location = 0) uniform int uOcclude;

int cellIndex(ivec3 v) {
  int n = params.resolution;
  return v.x + n * (v.y + n * v.z);
}
PropagationEntry entryAt(int e) { return entries[e]; }
int coefficientCount() { return params.coefficients; }
int colourCount() { return 3; }
int cellWords() {
  int values = 3 * params.coefficients;
  return params.halfPrecision == 0 ? values : packedCellWords(values);
}
float intensityAt(ivec3 cell, int word) {
  int first = cellIndex(cell) * cellWords();
  if (params.halfPrecision == 0) return uintBitsToFloat(previous[first + word]);
  return unpackStored(previous[first + word / 2], word % 2, params);
}
vec4 blockingAt(ivec3 g) {
  int n = params.resolution;
  if (any(lessThan(g, ivec3(0))) || any(greaterThanEqual(g, ivec3(n)))) return vec4(0.0f);
  return blocking[cellIndex(g)];
}
void storeIntensity(ivec3 cell, int word, float value) {
  if (params.halfPrecision == 0) {
    int w = cellIndex(cell) * cellWords() + word;
    next[w] = floatBitsToUint(value);
    float sum = accumulatedValue(uintBitsToFloat(accumulated[w]), value, params);
    accumulated[w] = floatBitsToUint(sum);
    return;
  }
  // This invocation owns its cell's words (padded), so reading back its own halves is safe.
  int w = cellIndex(cell) * cellWords() + word / 2;
  int part = word % 2;
  next[w] = packStored(next[w], part, value, params);
  float sum = accumulatedValue(unpackStored(accumulated[w], part, params), value, params);
  accumulated[w] = packStored(accumulated[w], part, sum, params);
}

#include "shared/lpv/propagate_kernel.h"

void main() {
  ivec3 x = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(x, ivec3(params.resolution)))) return;
  PropagateParams p = params;
  p.occlude = uOcclude;
  propagateCell(x, p);
}
