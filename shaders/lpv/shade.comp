#version 450 core
// shade: per pixel, the accumulated volume's irradiance and the analytic lights' direct light
// with the RSM depth as shadow map (shaders/shared/lpv/shade_kernel.h), and the final colour
// (shaders/shared/compose.h).
layout(local_size_x = 64) in;
#include "shared/lpv/lpv_types.h"
#include "shared/lighting.h"
#include "shared/compose.h"

uniform int uPixels;
uniform vec3 uBackground;
layout(std430, binding = 0) readonly buffer Params { ShadeParams params; };
layout(std430, binding = 1) readonly buffer Accumulated { float accumulated[]; };
layout(std430, binding = 2) readonly buffer Ids { uint ids[]; };
// per pixel: position, normal, albedo, emission (rgb, 3 floats each), specular (rgb, shininess)
layout(std430, binding = 3) readonly buffer Surfaces { float surfaces[]; };
layout(std430, binding = 4) writeonly buffer Indirect { float indirect[]; };
layout(std430, binding = 5) writeonly buffer Color { float color[]; };
layout(std430, binding = 6) readonly buffer Lights { LightData lights[]; };
layout(std430, binding = 7) readonly buffer Views {
  RsmParams rsm;
  RsmView views[];
};
layout(std430, binding = 8) readonly buffer Depth { float depths[]; };
layout(std430, binding = 9) writeonly buffer DirectDiffuse { float directDiffuse[]; };
layout(std430, binding = 10) writeonly buffer DirectSpecular { float directSpecular[]; };

float accumulatedAt(ivec3 cell, int word) {
  int n = params.resolution;
  if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, ivec3(n)))) return 0.0f;
  return accumulated[(cell.x + n * (cell.y + n * cell.z)) * 3 * params.coefficients + word];
}
LightData lightAt(int i) { return lights[i]; }
RsmView rsmViewAt(int i) { return views[i]; }
float rsmDepthAt(int view, ivec2 texel) {
  int r = rsm.resolution;
  return depths[(view * r + texel.y) * r + texel.x];
}

#include "shared/lpv/shade_kernel.h"

vec3 surface(int e, int field) {
  int w = 16 * e + 3 * field;
  return vec3(surfaces[w], surfaces[w + 1], surfaces[w + 2]);
}

void main() {
  int e = int(gl_GlobalInvocationID.x);
  if (e >= uPixels) return;
  uint id = ids[e];
  vec3 irradiance = vec3(0.0f), diffuse = vec3(0.0f), glossy = vec3(0.0f);
  if (id != 0u) {
    vec3 p = surface(e, 0), n = surface(e, 1);
    irradiance = lpvIrradiance(p, n, params);
    lpvDirect(p, n, surfaces[16 * e + 15], params, rsm, diffuse, glossy);
  }
  vec3 c = composePixel(id, surface(e, 2), surface(e, 4), surface(e, 3), diffuse, glossy,
                        irradiance, vec3(0.0f), 0.0f, uBackground);
  for (int k = 0; k < 3; ++k) {
    indirect[3 * e + k] = irradiance[k];
    color[3 * e + k] = c[k];
    directDiffuse[3 * e + k] = diffuse[k];
    directSpecular[3 * e + k] = glossy[k];
  }
}
