#version 450 core
// bounce: one diffuse bounce per voxel with the shared kernel (shaders/shared/cone/gather.h),
// gathering from the previous bounce's radiance and pyramid; gpu/vct/bounce.cpp rebuilds the pyramid
// with mip.comp between bounces.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#include "shared/cone/cone_types.h"
#include "cone_volumes.glsl"

layout(binding = 2) uniform sampler3D uDirect;  // light_voxels' radiance
layout(binding = 3) uniform sampler3D uAlbedo;
layout(binding = 4) uniform sampler3D uNormal;
layout(binding = 0, rgba32f) uniform writeonly image3D uBounced;

vec4 directAt(ivec3 v) { return texelFetch(uDirect, v, 0); }
vec3 albedoAt(ivec3 v) { return texelFetch(uAlbedo, v, 0).rgb; }
vec3 normalAt(ivec3 v) { return texelFetch(uNormal, v, 0).rgb; }
ConeData coneAt(int i);  // defined below, after the cone block

#include "shared/cone/gather.h"

layout(std430, binding = 0) readonly buffer Cones {
  ConeTraceParams params;
  ConeData cones[];
};

ConeData coneAt(int i) { return cones[i]; }

void main() {
  ivec3 v = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(v, ivec3(uResolution)))) return;
  imageStore(uBounced, v, bounceVoxel(v, params));
}
