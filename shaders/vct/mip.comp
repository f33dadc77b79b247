#version 450 core
// mip: one pyramid level from the level below with the shared kernel (shaders/shared/cone/mip.h).
// One invocation per voxel of every face; faces lie side by side along x.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#include "shared/glsl_cpp.h"

layout(binding = 0, rgba32f) uniform readonly image3D uSource;  // radiance, or the level below
layout(binding = 1, rgba32f) uniform writeonly image3D uTarget;
uniform int uSize;       // voxels per axis of one face at the target level
uniform int uFaces;      // 1 isotropic, 6 anisotropic
uniform bool uFromBase;  // the source is the radiance volume (one face for all)

vec4 childAt(int face, ivec3 c) {
  return imageLoad(uSource, uFromBase ? c : ivec3(c.x + face * 2 * uSize, c.y, c.z));
}

#include "shared/cone/mip.h"

void main() {
  ivec3 t = ivec3(gl_GlobalInvocationID);
  if (t.x >= uFaces * uSize || t.y >= uSize || t.z >= uSize) return;
  int face = t.x / uSize;
  ivec3 v = ivec3(t.x - face * uSize, t.y, t.z);
  imageStore(uTarget, t, uFaces == 1 ? mipIsotropic(v) : mipAnisotropic(v, face));
}
