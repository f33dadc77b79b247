// The voxel grid convention shared by every stage (docs/architecture.md, "Conventions"): an
// axis-aligned cube with `min` corner and edge `size`, N^3 voxels; voxel (i,j,k) covers min +
// [i,i+1)*h ... with h = size/N; voxel centres at min + (i+0.5)*h. Buffers store voxels x-fastest:
// index = i + N*(j + N*k).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>

namespace voxgi {

struct GridSpec {
  glm::dvec3 min{0.0};
  double size = 1.0;
  int resolution = 64;

  double voxelSize() const { return size / resolution; }
  uint64_t voxelCount() const {
    const auto n = static_cast<uint64_t>(resolution);
    return n * n * n;
  }
  // World position -> voxel-local coordinates (voxel (i,j,k) spans [i,i+1) on each axis).
  glm::dvec3 toVoxel(const glm::dvec3& world) const { return (world - min) * (resolution / size); }
  uint64_t index(const glm::ivec3& v) const {
    const auto n = static_cast<uint64_t>(resolution);
    return static_cast<uint64_t>(v.x) +
           n * (static_cast<uint64_t>(v.y) + n * static_cast<uint64_t>(v.z));
  }
};

// Largest resolution voxgi accepts at all (further limited by memory and the GL implementation).
constexpr int kMaxResolution = 2048;

}  // namespace voxgi
