// The octree's mip stage (docs/stages/svo/mip.md): the anisotropic six-face mipmap's golden values
// [Salm 2015, §4.4.2] (docs/svo.md, tests S10, S11), plain and NDF-weighted first step.
#include <gtest/gtest.h>

#include <cmath>

#include "cpu/svo/mip.h"
#include "tests/svo/tree_samples.h"

namespace voxgi::test {
namespace {

using namespace cpu::svo;

// A tree over one leaf tile's neighbourhood with chosen leaf values, for the mip golden values.
struct OneTile {
  Octree octree;
  Leaves leaves;
  LeafRadiance radiance;
};

// Leaves (local ids of the tile at the grid's origin) with premultiplied values and normals.
OneTile oneTile(const std::vector<std::pair<int, glm::vec4>>& values, glm::vec3 normal) {
  std::vector<shared::SvoSample> samples;
  for (const auto& [local, value] : values)
    samples.push_back(cellSample({local & 1, (local >> 1) & 1, local >> 2}));
  OneTile t{cpu::svo::buildOctree(samples, 2), {}, {}};
  const size_t slots = t.octree.leafTileCount() * 8;
  t.leaves.albedo.assign(slots, glm::vec4(0.0f));
  t.leaves.normal.assign(slots, glm::vec3(0.0f));
  t.leaves.emission.assign(slots, glm::vec3(0.0f));
  t.radiance.assign(slots, glm::vec4(0.0f));
  for (const auto& [local, value] : values) {
    t.radiance[size_t(local)] = value;  // the tile at the origin is leaf tile 0
    t.leaves.normal[size_t(local)] = normal;
  }
  return t;
}

// Node (0,0,0) of tree level 1 (the one above the leaves at depth 2), face f.
glm::vec4 parentFace(const OneTile& t, FirstStep first, int face) {
  const NodeLevels m = cpu::svo::mipTree(t.octree, t.leaves, t.radiance, first);
  return m.levels[1][size_t(face)];
}

// [Salm 2015, §4.4.2] golden values (S10, S11 of docs/svo.md), in voxgi's face labels: face f is
// what a cone travelling along f sees, Salm's value for the opposite direction.
TEST(SvoMip, AnisotropicGoldenValues) {
  constexpr int kPx = 0, kMx = 1, kPy = 2, kMy = 3, kPz = 4, kMz = 5;
  // One opaque child of radiance 1: a quarter in every face.
  OneTile one = oneTile({{0, glm::vec4(1.0f)}}, glm::vec3(0.0f));
  for (int f = 0; f < 6; ++f) EXPECT_EQ(parentFace(one, FirstStep::plain, f), glm::vec4(0.25f));
  // Two opaque children along x: radiance 1 at x = 0, 10 at x = 1.
  OneTile two = oneTile({{0, glm::vec4(1, 1, 1, 1)}, {1, glm::vec4(10, 10, 10, 1)}}, glm::vec3(0));
  EXPECT_EQ(parentFace(two, FirstStep::plain, kMx), glm::vec4(2.5f, 2.5f, 2.5f, 0.25f));
  EXPECT_EQ(parentFace(two, FirstStep::plain, kPx), glm::vec4(0.25f));
  for (const int f : {kPy, kMy, kPz, kMz})
    EXPECT_EQ(parentFace(two, FirstStep::plain, f), glm::vec4(2.75f, 2.75f, 2.75f, 0.5f));
  // Uniform opacity 0.3, radiance 2 in all eight: 1 - 0.7^2 along every face, radiance kept; the
  // faces are stored as halves, so each within half a ULP of a half (2^-12 in [0.5, 2)).
  std::vector<std::pair<int, glm::vec4>> all;
  for (int l = 0; l < 8; ++l) all.push_back({l, glm::vec4(0.6f, 0.6f, 0.6f, 0.3f)});
  const glm::vec4 uniform = parentFace(oneTile(all, glm::vec3(0.0f)), FirstStep::plain, kPz);
  EXPECT_NEAR(uniform.a, 1.0f - 0.7f * 0.7f, std::ldexp(1.0f, -12));
  EXPECT_NEAR(uniform.x, 2.0f * (1.0f - 0.7f * 0.7f), std::ldexp(1.0f, -11));
  // The NDF-weighted first step: an opaque wall in the x = 1 children facing +x.
  OneTile wall =
      oneTile({{1, glm::vec4(1)}, {3, glm::vec4(1)}, {5, glm::vec4(1)}, {7, glm::vec4(1)}},
              glm::vec3(1, 0, 0));
  EXPECT_EQ(parentFace(wall, FirstStep::ndf, kMx), glm::vec4(1.0f));  // seen from +x
  EXPECT_EQ(parentFace(wall, FirstStep::ndf, kPx), glm::vec4(0.0f));  // its back
  for (const int f : {kPy, kMy, kPz, kMz})
    EXPECT_EQ(parentFace(wall, FirstStep::ndf, f), glm::vec4(0.375f));
}

}  // namespace
}  // namespace voxgi::test
