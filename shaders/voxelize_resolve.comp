#version 450 core
// Resolves the voxelize sums to opacity and mean albedo, normal and emission, with the shared
// formulas (shaders/shared/voxelize_kernel.h). 3-component outputs are x-interleaved like the sums.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#include "shared/voxelize_kernel.h"

layout(std430, binding = 1) buffer Status { uint overflow; };
layout(binding = 0, r32ui) uniform readonly uimage3D uWeightSum;
layout(binding = 1, r32ui) uniform readonly uimage3D uAlbedoSum;
layout(binding = 2, r32i) uniform readonly iimage3D uNormalSum;
layout(binding = 3, r32ui) uniform readonly uimage3D uEmissionSum;
layout(binding = 4, r32f) uniform writeonly image3D uOpacityOut;
layout(binding = 5, r32f) uniform writeonly image3D uAlbedoOut;
layout(binding = 6, r32f) uniform writeonly image3D uNormalOut;
layout(binding = 7, r32f) uniform writeonly image3D uEmissionOut;
uniform int uResolution;
uniform bool uHasEmission;
uniform bool uAntialiased;
uniform float uEmissionScale;
uniform bool uEmitterMean;  // voxelize.emission=emitters: the mean over the emitting surfaces

uvec3 load3(ivec3 v) {
  return uvec3(imageLoad(uAlbedoSum, ivec3(3 * v.x, v.y, v.z)).x,
               imageLoad(uAlbedoSum, ivec3(3 * v.x + 1, v.y, v.z)).x,
               imageLoad(uAlbedoSum, ivec3(3 * v.x + 2, v.y, v.z)).x);
}

void main() {
  ivec3 v = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(v, ivec3(uResolution)))) return;
  uint w = imageLoad(uWeightSum, v).x;
  if (w > kMaxWeightSum) atomicOr(overflow, 1u);
  imageStore(uOpacityOut, v, vec4(resolveOpacity(w, uAntialiased)));
  vec3 albedo = resolveAverage(load3(v), w);
  ivec3 normalSum = ivec3(imageLoad(uNormalSum, ivec3(3 * v.x, v.y, v.z)).x,
                          imageLoad(uNormalSum, ivec3(3 * v.x + 1, v.y, v.z)).x,
                          imageLoad(uNormalSum, ivec3(3 * v.x + 2, v.y, v.z)).x);
  vec3 normal = resolveNormal(normalSum, w);
  vec3 emission = vec3(0.0f);
  if (uHasEmission) {
    uvec3 e = uvec3(imageLoad(uEmissionSum, ivec3(4 * v.x, v.y, v.z)).x,
                    imageLoad(uEmissionSum, ivec3(4 * v.x + 1, v.y, v.z)).x,
                    imageLoad(uEmissionSum, ivec3(4 * v.x + 2, v.y, v.z)).x);
    uint emitters = imageLoad(uEmissionSum, ivec3(4 * v.x + 3, v.y, v.z)).x;
    emission = resolveEmission(e, uEmitterMean ? emitters : w, uEmissionScale);
  }
  for (int c = 0; c < 3; ++c) {
    ivec3 texel = ivec3(3 * v.x + c, v.y, v.z);
    imageStore(uAlbedoOut, texel, vec4(albedo[c]));
    imageStore(uNormalOut, texel, vec4(normal[c]));
    if (uHasEmission) imageStore(uEmissionOut, texel, vec4(emission[c]));
  }
}
