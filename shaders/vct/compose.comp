#version 450 core
// compose: the shared final-colour kernel (shaders/shared/compose.h) per pixel.
layout(local_size_x = 64) in;
#include "shared/compose.h"

layout(location = 0) uniform int uPixels;
layout(location = 1) uniform vec3 uBackground;
layout(std430, binding = 0) readonly buffer Ids { uint ids[]; };
layout(std430, binding = 1) readonly buffer Inputs { ComposeInput inputs[]; };
layout(std430, binding = 2) writeonly buffer Color { float color[]; };

void main() {
  int e = int(gl_GlobalInvocationID.x);
  if (e >= uPixels) return;
  ComposeInput i = inputs[e];
  vec3 c = composePixel(ids[e], i.albedo.xyz, i.specular.xyz, i.emission.xyz, i.directDiffuse.xyz,
                        i.directSpecular.xyz, i.indirectDiffuse.xyz, i.indirectSpecular.xyz,
                        i.ambientOcclusion, uBackground);
  color[3 * e] = c.x;
  color[3 * e + 1] = c.y;
  color[3 * e + 2] = c.z;
}
