#version 450 core
// light_voxels: direct light per voxel with the shared kernel (shaders/shared/cone/voxel_light.h).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#include "shared/lighting.h"

layout(binding = 0) uniform sampler3D uOpacity;
layout(binding = 1) uniform sampler3D uAlbedo;
layout(binding = 2) uniform sampler3D uNormal;
layout(binding = 3) uniform sampler3D uEmission;
layout(binding = 4) uniform sampler3D uPrevious;  // the frame before's radiance, when partial
layout(binding = 0, rgba32f) uniform writeonly image3D uRadiance;

float opacityAt(ivec3 v) { return texelFetch(uOpacity, v, 0).r; }
vec3 albedoAt(ivec3 v) { return texelFetch(uAlbedo, v, 0).rgb; }
vec3 normalAt(ivec3 v) { return texelFetch(uNormal, v, 0).rgb; }
vec3 emissionAt(ivec3 v) { return texelFetch(uEmission, v, 0).rgb; }
LightData lightAt(int i);  // defined below, after the light block

#include "shared/cone/voxel_light.h"

layout(std430, binding = 0) readonly buffer Lights {
  LightVoxelsParams params;
  LightData lights[];
};

layout(std430, binding = 1) readonly buffer Update {
  LightVoxelsUpdate update;
};

LightData lightAt(int i) { return lights[i]; }

void main() {
  ivec3 v = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(v, ivec3(params.resolution)))) return;
  if (update.partial == 1 && !lightVoxelMayChange(v, params, update))
    imageStore(uRadiance, v, texelFetch(uPrevious, v, 0));
  else
    imageStore(uRadiance, v, lightVoxel(v, params));
}
