#include "cpu/cone/cell_occupancy.h"

#include <algorithm>

#include <tbb/blocked_range.h>

#include "common/parallel.h"

namespace voxgi::cpu {

CellOccupancy::CellOccupancy(const uint32_t* voxels, int s, int wordsPerVoxel)
    : side_(size_t(s) + 1) {
  const size_t n = size_t(s), side = side_, words = size_t(wordsPerVoxel);
  // Cell c (= lowest corner + 1) holds voxels c - 1 and c along each axis: dilate the voxel mask
  // by one towards +1 along x, then y, then z. Each task owns whole slices, so the result does
  // not depend on the thread count.
  std::vector<uint8_t> alongX(side * n * n), alongXY(side * side * n);
  parallelFor(tbb::blocked_range<size_t>(0, n * n), [&](const auto& rows) {
    for (size_t row = rows.begin(); row != rows.end(); ++row) {
      uint8_t previous = 0;
      for (size_t c = 0; c < side; ++c) {
        uint8_t any = 0;
        if (c < n) {
          const uint32_t* v = voxels + (row * n + c) * words;
          for (size_t k = 0; k < words; ++k) any |= v[k] != 0u;
        }
        alongX[row * side + c] = previous | any;
        previous = any;
      }
    }
  });
  parallelFor(tbb::blocked_range<size_t>(0, n), [&](const auto& slices) {
    for (size_t z = slices.begin(); z != slices.end(); ++z)
      for (size_t y = 0; y < side; ++y)
        for (size_t c = 0; c < side; ++c)
          alongXY[(z * side + y) * side + c] = (y < n ? alongX[(z * n + y) * side + c] : 0) |
                                               (y > 0 ? alongX[(z * n + y - 1) * side + c] : 0);
  });
  // 64 consecutive cells per word; a word may straddle slices, so words, not slices, are tasks.
  const size_t cells = side * side * side;
  bits_.assign((cells + 63) / 64, 0u);
  parallelFor(tbb::blocked_range<size_t>(0, bits_.size()), [&](const auto& range) {
    for (size_t w = range.begin(); w != range.end(); ++w)
      for (size_t c = w * 64; c < std::min(cells, w * 64 + 64); ++c) {
        const size_t z = c / (side * side), plane = c % (side * side);
        const bool any = (z < n && alongXY[z * side * side + plane] != 0) ||
                         (z > 0 && alongXY[(z - 1) * side * side + plane] != 0);
        bits_[w] |= uint64_t(any) << (c & 63);
      }
  });
}

}  // namespace voxgi::cpu
