// The mip stage on tiny volumes with known answers: the isotropic mean, the directional faces'
// front-to-back compositing (which child a cone along +x meets first), and the level layout.
#include <gtest/gtest.h>

#include "common/mips.h"
#include "cpu/stages.h"
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
  settings.mip = mode;
  BufferSet b;
  Buffer radiance(bufferSpec("light_voxels", "radiance"), glm::ivec3(4));
  for (int c = 0; c < 4; ++c) {
    radiance.set(0, c, kRed[c]);
    radiance.set(1, c, kBlue[c]);
  }
  b["radiance"] = std::move(radiance);
  const VoxelTriangles none{};
  cpu::mip(StageContext{scene, settings, none}, b);
  return b;
}

glm::vec4 at(const Buffer& b, size_t element) {
  return {b.get<float>(element, 0), b.get<float>(element, 1), b.get<float>(element, 2),
          b.get<float>(element, 3)};
}

TEST(Mip, IsotropicIsThePremultipliedMeanOfEightChildren) {
  const BufferSet b = mipOf(MipMode::isotropic);
  ASSERT_EQ(b.count("radiance_mips6"), 0u);  // only the pyramid the settings ask for
  const Buffer& mips = b.at("radiance_mips");
  EXPECT_EQ(mips.elementCount(), 8u + 1u);
  EXPECT_EQ(at(mips, 0), (kRed + kBlue) / 8.0f);  // level 1, voxel (0,0,0)
  EXPECT_EQ(at(mips, 1), glm::vec4(0.0f));
  EXPECT_EQ(at(mips, 8), (kRed + kBlue) / 64.0f);  // level 2: the mean of level 1
}

TEST(Mip, DirectionalFacesCompositeTheNearChildFirst) {
  const BufferSet b = mipOf(MipMode::anisotropic);
  const Buffer& mips = b.at("radiance_mips6");
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

}  // namespace
}  // namespace voxgi::test
