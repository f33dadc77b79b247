// Data shared by the CPU and GPU voxelizers: the per-triangle record (std430) and the fixed-point
// format of the accumulated sums. Included by C++ and GLSL.
#ifndef VOXGI_VOXELIZE_LAYOUT_H
#define VOXGI_VOXELIZE_LAYOUT_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// One triangle prepared for voxelization (common/voxel_triangles.cpp). Vertices are in voxel-local
// coordinates: voxel (i,j,k) covers [i,i+1)x[j,j+1)x[k,k+1). 144 bytes, std430-compatible.
struct VoxelTriangle {
  vec3 v0;
  float pad0;
  vec3 v1;
  float pad1;
  vec3 v2;
  float pad2;
  vec3 albedo;           // the material's constant (times its texture where it has one)
  float areaScale;       // true area / area projected on the dominant plane
  vec3 normal;           // unit geometric normal (world space)
  float sampleArea;      // area of one antialiasing sample
  vec3 emission;         // emission / emission scale, in [0, 1] (times its texture)
  float uvFootprint;     // texture-coordinate length of one voxel edge on the triangle
  uint dominantAxis;     // 0, 1 or 2: the axis the triangle is projected along
  uint subdivision;      // antialiasing subdivision n (n*n samples)
  uint albedoTexture;    // texture_kernel.h's record index, or kNoTexture
  uint emissionTexture;  // the same
  vec2 uv0;              // texture coordinates of v0, v1, v2
  vec2 uv1;
  vec2 uv2;
  vec2 pad3;
};

// Fixed point: one unit of the weight sum is 2^-16 voxel faces (h^2) of surface area.
// A voxel overflows past 2^31 units = 32768 h^2 of surface; both backends detect and report it.
const float kWeightScale = 65536.0f;
const uint kMaxWeightSum = 2147483647u;

// Sums one triangle adds to one voxel. albedo/emission/normal sums are weight * value, rounded.
struct VoxelContribution {
  uint weight;
  uint emitterWeight;  // the weight again when the triangle emits, else 0
  uvec3 albedo;
  ivec3 normal;
  uvec3 emission;
};

VOXGI_NAMESPACE_END
#endif
