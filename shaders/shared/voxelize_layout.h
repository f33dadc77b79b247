// Data shared by the CPU and GPU voxelizers: the per-triangle record (std430) and the fixed-point
// format of the accumulated sums. Included by C++ and GLSL.
#ifndef VOXGI_VOXELIZE_LAYOUT_H
#define VOXGI_VOXELIZE_LAYOUT_H
#include "glsl_cpp.h"

VOXGI_NAMESPACE_BEGIN

// One triangle prepared for voxelization (common/voxel_triangles.cpp). Vertices are in voxel-local
// coordinates: voxel (i,j,k) covers [i,i+1)x[j,j+1)x[k,k+1). 112 bytes, std430-compatible.
struct VoxelTriangle {
  vec4 v0;        // xyz: vertex 0
  vec4 v1;        // xyz: vertex 1
  vec4 v2;        // xyz: vertex 2
  vec4 albedo;    // rgb: albedo; w: area scale = true area / area projected on the dominant plane
  vec4 normal;    // xyz: unit geometric normal (world space); w: area of one antialiasing sample
  vec4 emission;  // rgb: emission / emission scale, in [0, 1]
  uint dominantAxis;  // 0, 1 or 2: the axis the triangle is projected along
  uint subdivision;   // antialiasing subdivision n (n*n samples)
  uint pad0;
  uint pad1;
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
