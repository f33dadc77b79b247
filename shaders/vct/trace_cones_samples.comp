#version 450 core
// trace_cones at cones.diffuse_scale = s > 1: the diffuse cones of each s x s block of pixels,
// traced from the block's sample pixel (shaders/shared/vct/diffuse_upsample.h), for
// trace_cones.comp to upsample.
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/lighting.h"
#include "shared/cone/cone_types.h"
#include "cone_volumes.glsl"

layout(location = 1) uniform int uWidth;
layout(location = 2) uniform int uHeight;

LightData lightAt(int i);  // defined below, after the buffers
ConeData coneAt(int i);

#include "shared/vct/diffuse_samples.h"

layout(std430, binding = 0) readonly buffer Lights {
  ConeTraceParams params;
  LightData lights[];
};
layout(std430, binding = 1) readonly buffer Cones { ConeData cones[]; };
layout(std430, binding = 3) readonly buffer Positions { float positions[]; };
layout(std430, binding = 4) readonly buffer Normals { float normals[]; };
layout(std430, binding = 5) readonly buffer Ids { uint ids[]; };
layout(std430, binding = 7) writeonly buffer Samples { DiffuseSample samples[]; };

LightData lightAt(int i) { return lights[i]; }
ConeData coneAt(int i) { return cones[i]; }

void main() {
  int scale = params.diffuseScale;
  ivec2 blocks = (ivec2(uWidth, uHeight) + scale - 1) / scale;
  ivec2 block = ivec2(gl_GlobalInvocationID.xy);
  if (block.x >= blocks.x || block.y >= blocks.y) return;
  DiffuseSample found = noDiffuseSample();
  for (int k = 0; k < scale * scale; ++k) {
    ivec2 px = block * scale + blockCandidate(k, scale);
    if (px.x >= uWidth || px.y >= uHeight) continue;
    int e = px.y * uWidth + px.x;
    if (ids[e] == 0u) continue;
    vec3 p = vec3(positions[3 * e], positions[3 * e + 1], positions[3 * e + 2]);
    vec3 n = vec3(normals[3 * e], normals[3 * e + 1], normals[3 * e + 2]);
    found = traceDiffuseSample(p, n, params);
    break;
  }
  samples[block.y * blocks.x + block.x] = found;
}
