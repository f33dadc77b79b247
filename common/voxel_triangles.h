// Triangle setup for the voxelize stage, shared by both backends: world triangles become
// VoxelTriangle records in voxel-local float coordinates (computed in double, so a scene far from
// the origin keeps its precision), degenerate ones are dropped, and triangles reaching past the
// grid are clipped to it (with one voxel of padding, the antialiasing kernel's reach).
#pragma once

#include <vector>

#include "common/scene.h"
#include "shaders/shared/voxelize_layout.h"

namespace voxgi {

// Input triangles a setup dropped or clipped.
struct VoxelTriangleCounts {
  size_t degenerate = 0;  // dropped for zero area
  size_t outside = 0;     // entirely outside the padded grid
  size_t clipped = 0;     // clipped at the padded grid boundary
};

struct VoxelTriangles {
  std::vector<shared::VoxelTriangle> triangles;
  // Mesh m's triangles are triangles[meshFirst[m], meshFirst[m + 1]) (clipped pieces included),
  // set up with meshCounts[m].
  std::vector<size_t> meshFirst{0};
  std::vector<VoxelTriangleCounts> meshCounts;
  float emissionScale = 0.0f;  // emission = VoxelTriangle::emission * emissionScale; 0 if none
  size_t degenerate = 0;       // the meshes' counts summed
  size_t outside = 0;
  size_t clipped = 0;
};

VoxelTriangles prepareVoxelTriangles(const Scene& scene, const GridSpec& grid);
// The same for a frame of a sequence: the meshes `unchanged` marks keep their triangles from
// `before` (set up from the same positions on the same grid), only the others are set up again.
VoxelTriangles prepareVoxelTriangles(const Scene& scene, const GridSpec& grid,
                                     const VoxelTriangles& before,
                                     const std::vector<bool>& unchanged);

// Dominant axis of a normal: the index of its largest |component| (ties go to the lower index).
unsigned dominantAxis(const glm::dvec3& n);

}  // namespace voxgi
