#version 450 core
// compose: the shared final-colour kernel (shaders/shared/compose_kernel.h) per pixel.
layout(local_size_x = 64) in;
#include "shared/compose_kernel.h"

layout(location = 0) uniform int uPixels;
layout(location = 1) uniform vec3 uBackground;
layout(std430, binding = 0) readonly buffer Ids { uint ids[]; };
// 22 floats per pixel: albedo, specular colour, emission, direct diffuse, direct specular,
// indirect diffuse, indirect specular (rgb each), ambient occlusion.
layout(std430, binding = 1) readonly buffer Inputs { float inputs[]; };
layout(std430, binding = 2) writeonly buffer Color { float color[]; };

vec3 rgb(int e, int term) {
  int i = 22 * e + 3 * term;
  return vec3(inputs[i], inputs[i + 1], inputs[i + 2]);
}

void main() {
  int e = int(gl_GlobalInvocationID.x);
  if (e >= uPixels) return;
  vec3 c = composePixel(ids[e], rgb(e, 0), rgb(e, 1), rgb(e, 2), rgb(e, 3), rgb(e, 4), rgb(e, 5),
                        rgb(e, 6), inputs[22 * e + 21], uBackground);
  color[3 * e] = c.x;
  color[3 * e + 1] = c.y;
  color[3 * e + 2] = c.z;
}
