#version 450 core
// trace_cones: the shared per-pixel cone tracer (shaders/shared/cone/pixel_light.h) on the
// gbuffer; at cones.diffuse_scale > 1 a pixel's diffuse light is upsampled from the blocks'
// samples that trace_cones_samples.comp traced (shaders/shared/vct/diffuse_upsample.h).
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/lighting.h"
#include "shared/cone/cone_types.h"
#include "cone_volumes.glsl"

layout(location = 1) uniform int uWidth;
layout(location = 2) uniform int uHeight;

LightData lightAt(int i);  // defined below, after the buffers
ConeData coneAt(int i);
DiffuseSample diffuseSampleAt(ivec2 block);

#include "shared/vct/diffuse_upsample.h"

layout(std430, binding = 0) readonly buffer Lights {
  ConeTraceParams params;
  LightData lights[];
};
layout(std430, binding = 1) readonly buffer Cones { ConeData cones[]; };
layout(std430, binding = 2) readonly buffer Objects { ObjectData objects[]; };
layout(std430, binding = 3) readonly buffer Positions { float positions[]; };
layout(std430, binding = 4) readonly buffer Normals { float normals[]; };
layout(std430, binding = 5) readonly buffer Ids { uint ids[]; };
layout(std430, binding = 6) writeonly buffer Terms { PixelTerms terms[]; };
layout(std430, binding = 7) readonly buffer Samples { DiffuseSample samples[]; };

LightData lightAt(int i) { return lights[i]; }
ConeData coneAt(int i) { return cones[i]; }
DiffuseSample diffuseSampleAt(ivec2 block) {
  int scale = params.diffuseScale;
  ivec2 blocks = (ivec2(uWidth, uHeight) + scale - 1) / scale;
  if (any(lessThan(block, ivec2(0))) || any(greaterThanEqual(block, blocks)))
    return noDiffuseSample();
  return samples[block.y * blocks.x + block.x];
}

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (px.x >= uWidth || px.y >= uHeight) return;
  int e = px.y * uWidth + px.x;
  uint id = ids[e];
  PixelLight l = PixelLight(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0);
  if (id != 0u) {
    vec3 p = vec3(positions[3 * e], positions[3 * e + 1], positions[3 * e + 2]);
    vec3 n = vec3(normals[3 * e], normals[3 * e + 1], normals[3 * e + 2]);
    l = shadePixel(p, n, objects[id], pixelDiffuse(px, p, n, params), params);
  }
  terms[e] = PixelTerms(vec4(l.directDiffuse, 0.0f), vec4(l.directSpecular, 0.0f),
                        vec4(l.indirectDiffuse, 0.0f), vec4(l.indirectSpecular, 0.0f),
                        vec4(l.ambientOcclusion, 0.0f, 0.0f, 0.0f));
}
