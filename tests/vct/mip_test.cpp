// The mip stage on tiny volumes with known answers: the isotropic mean, the directional faces'
// front-to-back compositing (which child a cone along +x meets first), and the level layout.
#include <gtest/gtest.h>

#include "common/mips.h"
#include "cpu/stages.h"
#include "shaders/shared/cone/mip.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

const glm::vec4 kRed(1, 0, 0, 1), kBlue(0, 0, 1, 1);

// A 4^3 radiance volume with an opaque red voxel at (0,0,0) and an opaque blue one at (1,0,0):
// the first level-1 voxel holds them side by side along x.
BufferSet mipOf(MipMode mode) {
  Scene scene;
  scene.grid = unitGrid(4);
  Settings settings;
  settings.vct.mip = mode;
  BufferSet b;
  Buffer radiance(BufferId::vct_light_voxels_radiance, glm::ivec3(4));
  for (int c = 0; c < 4; ++c) {
    radiance.set(0, c, kRed[c]);
    radiance.set(1, c, kBlue[c]);
  }
  b.put(std::move(radiance));
  const VoxelTriangles none{};
  cpu::vct::mip(StageContext{vct(), scene, settings, none}, b);
  return b;
}

glm::vec4 at(const Buffer& b, size_t element) {
  return {b.get<float>(element, 0), b.get<float>(element, 1), b.get<float>(element, 2),
          b.get<float>(element, 3)};
}

TEST(Mip, IsotropicIsThePremultipliedMeanOfEightChildren) {
  const BufferSet b = mipOf(MipMode::isotropic);
  ASSERT_FALSE(b.contains(BufferId::vct_mip_radiance_mips6));  // only the pyramid asked for
  const Buffer& mips = b.at(BufferId::vct_mip_radiance_mips);
  EXPECT_EQ(mips.elementCount(), 8u + 1u);
  EXPECT_EQ(at(mips, 0), (kRed + kBlue) / 8.0f);  // level 1, voxel (0,0,0)
  EXPECT_EQ(at(mips, 1), glm::vec4(0.0f));
  EXPECT_EQ(at(mips, 8), (kRed + kBlue) / 64.0f);  // level 2: the mean of level 1
}

TEST(Mip, DirectionalFacesCompositeTheNearChildFirst) {
  const BufferSet b = mipOf(MipMode::anisotropic);
  const Buffer& mips = b.at(BufferId::vct_mip_radiance_mips6);
  EXPECT_EQ(mips.elementCount(), 6u * (8u + 1u));
  // Level 1 is 12 x 2 x 2: face f's voxel (0,0,0) is element 2f.
  auto face = [&](int f) { return at(mips, size_t(2 * f)); };
  // Travelling along +x a cone meets red first (it hides blue); along -x it meets blue. One of
  // the four child pairs is filled: each face is a quarter.
  EXPECT_EQ(face(0), kRed / 4.0f);
  EXPECT_EQ(face(1), kBlue / 4.0f);
  // Across the pair (y, z faces) both children are seen side by side: (red + blue) / 4.
  for (int f = 2; f < 6; ++f) EXPECT_EQ(face(f), (kRed + kBlue) / 4.0f) << f;
  // Level 2 (one voxel per face) composites the level-1 faces the same way.
  const size_t level2 = mipLevelOffset(4, 2, 6);
  EXPECT_EQ(level2, 6u * 8u);
  EXPECT_EQ(at(mips, level2 + 0), kRed / 16.0f);
  EXPECT_EQ(at(mips, level2 + 1), kBlue / 16.0f);
}

// The CPU writes the directional faces with the shared kernel's arithmetic unrolled over rows
// (cpu/vct/pyramid.cpp); every face of every level must equal shared::mipAnisotropic bit for bit,
// here on semi-transparent random premultiplied values.
TEST(Mip, DirectionalRowsMatchTheSharedKernelBitForBit) {
  constexpr int n = 16;
  Scene scene;
  scene.grid = unitGrid(n);
  Settings settings;
  BufferSet b;
  Buffer radiance(BufferId::vct_light_voxels_radiance, glm::ivec3(n));
  uint32_t state = 12345u;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return float(state >> 8) / float(1u << 24);
  };
  for (size_t e = 0; e < radiance.elementCount(); ++e) {
    const float a = next() < 0.3f ? 0.0f : next();
    for (int c = 0; c < 3; ++c) radiance.set(e, c, a * next() * 4.0f);
    radiance.set(e, 3, a);
  }
  b.put(radiance);
  const VoxelTriangles none{};
  cpu::vct::mip(StageContext{vct(), scene, settings, none}, b);
  const Buffer& mips = b.at(BufferId::vct_mip_radiance_mips6);
  // Children of level l from level l - 1 (level 0: the radiance volume, shared by every face).
  struct Below {
    const Buffer& radiance;
    const Buffer& mips;
    int level;
    glm::vec4 childAt(int face, glm::ivec3 c) const {
      if (level == 1) return voxelValue(radiance, c);
      const int size = n >> (level - 1);
      const size_t e = mipLevelOffset(n, level - 1, 6) + size_t(c.x + face * size) +
                       size_t(6 * size) * (size_t(c.y) + size_t(size) * size_t(c.z));
      return at(mips, e);
    }
  };
  size_t compared = 0;
  for (int level = 1; level <= mipLevelCount(n); ++level) {
    const int s = n >> level;
    const Below below{radiance, mips, level};
    for (int z = 0; z < s; ++z)
      for (int y = 0; y < s; ++y)
        for (int face = 0; face < 6; ++face)
          for (int x = 0; x < s; ++x) {
            const glm::vec4 expected = shared::mipAnisotropic(below, glm::ivec3(x, y, z), face);
            const size_t e = mipLevelOffset(n, level, 6) + size_t(x + face * s) +
                             size_t(6 * s) * (size_t(y) + size_t(s) * size_t(z));
            const glm::vec4 got = at(mips, e);
            for (int c = 0; c < 4; ++c)
              ASSERT_EQ(std::bit_cast<uint32_t>(got[c]), std::bit_cast<uint32_t>(expected[c]))
                  << "level " << level << " face " << face << " voxel " << x << "," << y << ","
                  << z;
            ++compared;
          }
  }
  EXPECT_EQ(compared, 6u * (512u + 64u + 8u + 1u));
}

}  // namespace
}  // namespace voxgi::test
