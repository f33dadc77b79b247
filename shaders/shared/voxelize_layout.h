// Data shared by the CPU and GPU voxelizers: the per-triangle record (std430) and the fixed-point
// format of the accumulated sums. Included by C++ and GLSL.
#ifndef VOXGI_VOXELIZE_LAYOUT_H
#define VOXGI_VOXELIZE_LAYOUT_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// One triangle prepared for voxelization (common/voxel_triangles.cpp). Vertices are in voxel-local
// coordinates: voxel (i,j,k) covers [i,i+1)x[j,j+1)x[k,k+1). 112 bytes, std430-compatible.
struct VoxelTriangle {
  vec3 v0;
  float pad0;
  vec3 v1;
  float pad1;
  vec3 v2;
  float pad2;
  vec3 albedo;
  float areaScale;   // true area / area projected on the dominant plane
  vec3 normal;       // unit geometric normal (world space)
  float sampleArea;  // area of one antialiasing sample
  vec3 emission;     // emission / emission scale, in [0, 1]
  float pad3;
  uint dominantAxis;  // 0, 1 or 2: the axis the triangle is projected along
  uint subdivision;   // antialiasing subdivision n (n*n samples)
  uint pad4;
  uint pad5;
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
