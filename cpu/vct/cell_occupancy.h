// Which trilinear cells of a volume hold anything, for the CPU cone tracer (FETCH(cellEmpty)):
// a sample whose 8 voxels are all +0 in every word and face is exactly +0, so the tracer returns
// vec4(0) without reading them. Nearly half the samples of a typical scene fall in empty space.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace voxgi::cpu {

class CellOccupancy {
 public:
  CellOccupancy() = default;
  // `voxels`: s^3 voxels of `wordsPerVoxel` consecutive words each, x fastest.
  CellOccupancy(const uint32_t* voxels, int s, int wordsPerVoxel);

  // True when every voxel of the cell whose lowest corner is `i` (i in [-1, s-1]^3, voxels
  // outside the volume read as 0) is +0 in every word.
  bool empty(glm::ivec3 i) const { return empty(i.x, i.y, i.z); }
  // Always inlined: the cone lanes built for AVX2 call it, and an out-of-line copy compiled there
  // could be the one the whole program links (tests/simd_symbols_test.cmake).
  [[gnu::always_inline]] bool empty(int x, int y, int z) const {
    const size_t c = size_t(x + 1) + side_ * (size_t(y + 1) + side_ * size_t(z + 1));
    return (bits_.data()[c >> 6] >> (c & 63) & 1u) == 0u;
  }

 private:
  size_t side_ = 0;  // s + 1 cells a side
  std::vector<uint64_t> bits_;
};

}  // namespace voxgi::cpu
