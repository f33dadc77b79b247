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
  bool empty(glm::ivec3 i) const {
    const size_t c = size_t(i.x + 1) + side_ * (size_t(i.y + 1) + side_ * size_t(i.z + 1));
    return (bits_[c >> 6] >> (c & 63) & 1u) == 0u;
  }
  // The bits as empty() reads them (cell c's bit: c >> 6, c & 63), and the cells a side, for the
  // cone lanes, which read them without calling into this class (cpu/cone/cone_lanes.h).
  const uint64_t* bits() const { return bits_.data(); }
  size_t side() const { return side_; }

 private:
  size_t side_ = 0;  // s + 1 cells a side
  std::vector<uint64_t> bits_;
};

}  // namespace voxgi::cpu
