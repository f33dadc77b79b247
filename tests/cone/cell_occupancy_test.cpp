// The CPU cone tracer's empty-cell mask (cpu/cone/cell_occupancy.h) against a brute-force scan of
// each cell's 8 voxels, on a sparse random volume with voxels on the borders and -0.0 words.
#include <bit>
#include <random>

#include <gtest/gtest.h>

#include "cpu/cone/cell_occupancy.h"

namespace voxgi::test {
namespace {

TEST(CellOccupancy, MatchesTheEightVoxelsOfEveryCell) {
  for (const int words : {4, 24}) {
    const int s = 9;
    std::vector<uint32_t> voxels(size_t(s * s * s * words), 0u);
    std::mt19937 random(7);  // 32-bit words
    for (int k = 0; k < 12; ++k) {
      const size_t voxel = random() % size_t(s * s * s);
      // Only one word set: the mask must look at every word of every face; -0.0 is not +0.
      voxels[voxel * size_t(words) + random() % size_t(words)] =
          k % 3 == 0 ? std::bit_cast<uint32_t>(-0.0f) : uint32_t(random()) | 1u;
    }
    voxels[size_t(s * s * s - 1) * size_t(words) + size_t(words - 1)] = 1u;  // the far corner
    const cpu::CellOccupancy occupancy(voxels.data(), s, words);
    const auto occupied = [&](glm::ivec3 v) {
      if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= s || v.y >= s || v.z >= s) return false;
      const size_t voxel = size_t(v.x + s * (v.y + s * v.z));
      for (int w = 0; w < words; ++w)
        if (voxels[voxel * size_t(words) + size_t(w)] != 0u) return true;
      return false;
    };
    int empty = 0;
    for (int z = -1; z < s; ++z)
      for (int y = -1; y < s; ++y)
        for (int x = -1; x < s; ++x) {
          bool any = false;
          for (int c = 0; c < 8; ++c)
            any = any || occupied(glm::ivec3(x + (c & 1), y + (c >> 1 & 1), z + (c >> 2)));
          EXPECT_EQ(occupancy.empty(glm::ivec3(x, y, z)), !any) << x << ' ' << y << ' ' << z;
          empty += any ? 0 : 1;
        }
    EXPECT_GT(empty, 0);
    EXPECT_LT(empty, (s + 1) * (s + 1) * (s + 1));
  }
}

}  // namespace
}  // namespace voxgi::test
