// Where each level of a mip pyramid lives in a flat buffer (BufferShape::mips and mips6). Level 0
// is the volume itself (a separate buffer); levels 1..levelCount(N) follow one another, level l
// holding `faces` volumes of (N>>l)^3 voxels side by side along x.
#pragma once

#include <bit>
#include <cstdint>

namespace voxgi {

// Levels above the base of an N^3 volume (N a power of two): N>>levelCount(N) == 1.
inline int mipLevelCount(int resolution) {
  return std::countr_zero(static_cast<unsigned>(resolution));
}

inline uint64_t mipLevelElements(int resolution, int level, int faces) {
  const auto s = static_cast<uint64_t>(resolution >> level);
  return uint64_t(faces) * s * s * s;
}

// First element of `level` (1-based; level mipLevelCount(N) + 1 gives the total).
inline uint64_t mipLevelOffset(int resolution, int level, int faces) {
  uint64_t offset = 0;
  for (int l = 1; l < level; ++l) offset += mipLevelElements(resolution, l, faces);
  return offset;
}

}  // namespace voxgi
