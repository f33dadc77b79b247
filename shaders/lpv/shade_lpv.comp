#version 450 core
// shade_lpv: per pixel, the accumulated volume's irradiance (shaders/shared/lpv/shade_kernel.h)
// and the final colour (shaders/shared/compose_kernel.h).
layout(local_size_x = 64) in;
#include "shared/lpv/lpv_types.h"
#include "shared/compose_kernel.h"

layout(location = 0) uniform int uPixels;
layout(location = 1) uniform vec3 uBackground;
layout(std430, binding = 0) readonly buffer Params { ShadeParams params; };
layout(std430, binding = 1) readonly buffer Accumulated { float accumulated[]; };
layout(std430, binding = 2) readonly buffer Ids { uint ids[]; };
// per pixel: position, normal, albedo, emission (rgb, 3 floats each)
layout(std430, binding = 3) readonly buffer Surfaces { float surfaces[]; };
layout(std430, binding = 4) writeonly buffer Indirect { float indirect[]; };
layout(std430, binding = 5) writeonly buffer Color { float color[]; };

float accumulatedAt(ivec3 cell, int word) {
  int n = params.shape.x;
  if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, ivec3(n)))) return 0.0f;
  return accumulated[(cell.x + n * (cell.y + n * cell.z)) * 3 * params.shape.y + word];
}

#include "shared/lpv/shade_kernel.h"

vec3 surface(int e, int field) {
  int w = 12 * e + 3 * field;
  return vec3(surfaces[w], surfaces[w + 1], surfaces[w + 2]);
}

void main() {
  int e = int(gl_GlobalInvocationID.x);
  if (e >= uPixels) return;
  uint id = ids[e];
  vec3 irradiance = id == 0u ? vec3(0.0f) : lpvIrradiance(surface(e, 0), surface(e, 1), params);
  vec3 zero = vec3(0.0f);
  vec3 c = composePixel(id, surface(e, 2), zero, surface(e, 3), zero, zero, irradiance, zero, 0.0f,
                        uBackground);
  for (int k = 0; k < 3; ++k) {
    indirect[3 * e + k] = irradiance[k];
    color[3 * e + k] = c[k];
  }
}
