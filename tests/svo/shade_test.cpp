// Shading's sample of the leaves' gathered light (shaders/shared/svo/shade_kernel.h), S18 of
// docs/svo.md: a constant field shades constant, the trilinear sample at a leaf centre is that
// leaf, and the cubic B-spline reproduces a linear field.
#include <gtest/gtest.h>

#include <bit>

#include "cpu/svo/svo_volumes.h"
#include "shaders/shared/svo/shade_kernel.h"
#include "tests/svo/tree_samples.h"

namespace voxgi {
namespace {

constexpr int kDepth = 4;  // 16^3 leaves, every one holding a sample

struct FullTree {
  cpu::svo::Octree octree;
  voxgi::svo::Leaves leaves;
  Words bricks;
};

// A sample at every leaf centre (a one-leaf RoI: all its weight in that leaf), and gathered light
// f(leaf centre) with opacity `opacity` per leaf, premultiplied, completed into bricks.
template <class F>
FullTree fullTree(const F& f, float opacity) {
  const int n = 1 << kDepth;
  std::vector<shared::SvoSample> samples;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) samples.push_back(test::cellSample({i, j, k}));
  FullTree t{cpu::svo::buildOctree(samples, kDepth), {}, {}};
  const size_t slots = t.octree.leafTileCount() * 8;
  t.leaves.albedo.assign(slots, glm::vec4(0.5f, 0.5f, 0.5f, opacity));
  t.leaves.normal.assign(slots, glm::vec3(0.0f));
  t.leaves.emission.assign(slots, glm::vec3(0.0f));
  Words interior(slots * 4);
  cpu::svo::forEachRealLeaf(t.octree, [&](size_t slot, glm::ivec3 v) {
    const glm::vec3 value = f(glm::vec3(v) + 0.5f) * opacity;
    for (int c = 0; c < 3; ++c) interior[slot * 4 + size_t(c)] = std::bit_cast<uint32_t>(value[c]);
    interior[slot * 4 + 3] = std::bit_cast<uint32_t>(opacity);
  });
  t.bricks = cpu::svo::completeBricks(t.octree, kDepth, interior, 4);
  return t;
}

cpu::svo::SvoVolumes volumesOf(const FullTree& t) {
  cpu::svo::SvoVolumes v{t.octree, t.leaves};
  v.leafBricks = &t.bricks;
  return v;
}

TEST(SvoShade, ConstantGatheredLightShadesConstant) {
  const glm::vec3 c(0.3f, 0.5f, 0.7f);
  const FullTree t = fullTree([&](glm::vec3) { return c; }, 0.6f);
  const cpu::svo::SvoVolumes v = volumesOf(t);
  for (const glm::vec3 p :
       {glm::vec3(3.2f, 7.9f, 5.5f), glm::vec3(8.0f), glm::vec3(2.1f, 12.7f, 9.3f)})
    for (const glm::vec3 e :
         {shared::svoIrradiance(v, p, kDepth), shared::svoIrradianceTricubic(v, p, kDepth)})
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[k], c[k], 1e-6f) << p.x << " " << p.y << " " << p.z;
}

TEST(SvoShade, TrilinearAtALeafCentreIsThatLeaf) {
  const auto f = [](glm::vec3 q) { return glm::vec3(q.x * 0.01f, q.y * q.y * 0.001f, 0.2f); };
  const FullTree t = fullTree(f, 1.0f);
  const cpu::svo::SvoVolumes v = volumesOf(t);
  for (const glm::ivec3 leaf : {glm::ivec3(0), glm::ivec3(5, 9, 2), glm::ivec3(15)}) {
    const glm::vec3 centre = glm::vec3(leaf) + 0.5f;
    EXPECT_EQ(shared::svoIrradiance(v, centre, kDepth), f(centre));
  }
}

// The cubic B-spline reproduces polynomials of degree 1: away from the grid's border (where the
// missing leaves outside count as empty), a linear field comes back at any point.
TEST(SvoShade, TricubicReproducesALinearField) {
  const auto f = [](glm::vec3 q) {
    return glm::vec3(0.1f + 0.02f * q.x, 0.3f - 0.01f * q.y + 0.005f * q.z, 0.05f * q.z);
  };
  const FullTree t = fullTree(f, 1.0f);
  const cpu::svo::SvoVolumes v = volumesOf(t);
  for (const glm::vec3 p :
       {glm::vec3(4.3f, 7.7f, 9.1f), glm::vec3(8.0f, 8.5f, 6.25f), glm::vec3(12.9f, 3.1f, 11.4f)}) {
    const glm::vec3 e = shared::svoIrradianceTricubic(v, p, kDepth);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(e[k], f(p)[k], 1e-5f) << p.x << " " << p.y << " " << p.z;
  }
  // On a curved field the cubic sample smooths: it is not the trilinear one.
  const auto curved = [](glm::vec3 q) { return glm::vec3(0.002f * q.x * q.x); };
  const FullTree c = fullTree(curved, 1.0f);
  const cpu::svo::SvoVolumes w = volumesOf(c);
  const glm::vec3 p(7.3f, 8.2f, 5.6f);
  EXPECT_GT(std::abs(shared::svoIrradianceTricubic(w, p, kDepth).x -
                     shared::svoIrradiance(w, p, kDepth).x),
            1e-4f);
}

}  // namespace
}  // namespace voxgi
