// Triangle setup for the voxelize stage, shared by both backends: world triangles become
// VoxelTriangle records in voxel-local float coordinates (computed in double, so a scene far from
// the origin keeps its precision), degenerate ones are dropped, and triangles reaching past the
// grid are clipped to it (with one voxel of padding, the antialiasing kernel's reach).
#pragma once

#include <vector>

#include "common/scene.h"
#include "shaders/shared/voxelize_layout.h"

namespace voxgi {

struct VoxelTriangles {
  std::vector<shared::VoxelTriangle> triangles;
  float emissionScale = 0.0f;  // emission = VoxelTriangle::emission * emissionScale; 0 if none
  size_t degenerate = 0;       // input triangles dropped for zero area
  size_t outside = 0;          // input triangles entirely outside the padded grid
  size_t clipped = 0;          // input triangles clipped at the padded grid boundary
};

VoxelTriangles prepareVoxelTriangles(const Scene& scene, const GridSpec& grid);

// Dominant axis of a normal: the index of its largest |component| (ties go to the lower index).
unsigned dominantAxis(const glm::dvec3& n);

}  // namespace voxgi
