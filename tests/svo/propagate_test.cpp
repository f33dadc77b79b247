// The octree's propagate stage (docs/stages/svo/propagate.md; docs/svo.md, tests S9, S15, S17 and
// the dense oracle): the shared kernels read through the tree give the dense pyramid's results on
// the same voxels; progressive bounces as the explicit sum; injection.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "common/mips.h"
#include "common/svo/stage_inputs.h"
#include "common/stage.h"
#include "common/cone/cone_sets.h"
#include "common/cone/cone_trace.h"
#include "cpu/svo/mip.h"
#include "cpu/svo/propagate.h"
#include "cpu/svo/svo_volumes.h"
#include "cpu/cone/cone_volumes.h"
#include "cpu/cone/gather_lanes.h"
#include "shaders/shared/half_float.h"
#include "shaders/shared/cone/mip.h"
#include "shaders/shared/cone/gather.h"
#include "tests/svo/tree_samples.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

using cpu::svo::FirstStep;
using cpu::svo::LeafRadiance;
using cpu::svo::Leaves;
using cpu::svo::NodeLevels;
using cpu::svo::Octree;
using cpu::svo::SvoVolumes;

// The furnace: a closed box whose walls all emit (as tests/vct/bounce_test.cpp).
Scene furnace(int n) {
  Material m;
  m.albedo = glm::vec3(0.5f, 0.6f, 0.7f);
  m.emission = glm::vec3(1.0f, 0.5f, 0.25f);
  return closedBox(n, m);
}

// The dense side of the oracle: the bounce kernel's reads from the voxelize, light_voxels and
// mip buffers.
struct DenseVolumes {
  const cpu::ConeVolumes& pyramid;
  const Buffer& direct;
  const Buffer& albedo;
  const Buffer& normal;
  const GridSpec& grid;
  glm::vec4 pyramidAt(int level, int face, glm::ivec3 v) const {
    return pyramid.pyramidAt(level, face, v);
  }
  bool cellEmpty(int, glm::ivec3) const { return false; }
  shared::ConeData coneAt(int i) const { return pyramid.coneAt(i); }
  glm::vec4 directAt(glm::ivec3 v) const { return voxelValue(direct, v); }
  glm::vec3 albedoAt(glm::ivec3 v) const { return glm::vec3(voxelValue(albedo, v)); }
  glm::vec3 normalAt(glm::ivec3 v) const { return glm::vec3(voxelValue(normal, v)); }
};

bool sameBits(glm::vec4 a, glm::vec4 b) {
  for (int c = 0; c < 4; ++c)
    if (std::bit_cast<uint32_t>(a[c]) != std::bit_cast<uint32_t>(b[c])) return false;
  return true;
}

// An octree whose leaves are the occupied voxels of the dense pipeline's grid (run up to `last`),
// holding their values: the albedo with opacity 1 (so that the kernels' albedo is the dense albedo
// bit for bit), the normal sum, and light_voxels' radiance (which carries the dense opacity).
// The directional pyramid the octree's six-face mipmap mirrors.
Settings anisotropicMip() {
  Settings settings;
  settings.vct.mip = MipMode::anisotropic;
  return settings;
}

// The closed box at 2^depth, its dense CPU run up to `last`, and an octree whose leaves hold the
// dense grid's occupied voxels, with the bounce's cone setup for a tree of that depth.
struct DenseTree {
  Scene scene;
  Settings settings;
  BufferSet dense;
  std::vector<shared::SvoSample> samples;
  Octree octree;
  Leaves leaves;
  LeafRadiance radiance;
  ConeTraceSetup bounce;
};

DenseTree denseTree(int depth, const char* last) {
  const int n = 1 << depth;
  DenseTree t;
  t.scene = furnace(n);
  t.settings = anisotropicMip();
  t.dense = runCpuUntil(t.scene, t.settings, last);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        if (voxelValue(t.dense.at(BufferId::common_voxelize_opacity), {x, y, z}).x > 0.0f)
          t.samples.push_back(cellSample({x, y, z}));
  t.octree = cpu::svo::buildOctree(t.samples, depth);
  const size_t slots = t.octree.leafTileCount() * 8;
  t.leaves.albedo.assign(slots, glm::vec4(0.0f));
  t.leaves.normal.assign(slots, glm::vec3(0.0f));
  t.leaves.emission.assign(slots, glm::vec3(0.0f));
  t.radiance.assign(slots, glm::vec4(0.0f));
  cpu::svo::forEachRealLeaf(t.octree, [&](size_t slot, glm::ivec3 v) {
    t.leaves.albedo[slot] =
        glm::vec4(glm::vec3(voxelValue(t.dense.at(BufferId::common_voxelize_albedo), v)), 1.0f);
    t.leaves.normal[slot] = glm::vec3(voxelValue(t.dense.at(BufferId::common_voxelize_normal), v));
    t.radiance[slot] = voxelValue(t.dense.at(BufferId::vct_light_voxels_radiance), v);
  });
  const auto tris = prepareVoxelTriangles(t.scene, t.scene.grid);
  t.bounce = prepareGather(StageContext(vct(), t.scene, t.settings, tris));
  t.bounce.params.topLevel = depth - 1;  // the octree's top is the root tile, 2^3 voxels
  return t;
}

// The dense directional pyramid (vct's mip.radiance_mips6 layout, common/mips.h) as the octree's
// pools hold it: each level mipped by the shared kernel from the level below as stored, and each
// face rounded to halves.
Buffer storedPyramid(const Buffer& radiance, const Buffer& mips6, int n) {
  struct Below {
    const Buffer& radiance;
    const Buffer& pyramid;
    int n, level;  // the level being mipped
    glm::vec4 childAt(int face, glm::ivec3 c) const {
      if (level == 1) return voxelValue(radiance, c);
      const int s = n >> (level - 1);
      const size_t e =
          mipLevelOffset(n, level - 1, 6) + size_t((c.z * s + c.y) * 6 * s + face * s + c.x);
      return {pyramid.get<float>(e, 0), pyramid.get<float>(e, 1), pyramid.get<float>(e, 2),
              pyramid.get<float>(e, 3)};
    }
  };
  Buffer out = mips6;
  for (int level = 1; level <= mipLevelCount(n); ++level) {
    const Below below{radiance, out, n, level};
    const int s = n >> level;
    for (int z = 0; z < s; ++z)
      for (int y = 0; y < s; ++y)
        for (int face = 0; face < 6; ++face)
          for (int x = 0; x < s; ++x) {
            const glm::vec4 v =
                shared::roundToHalf4(shared::mipAnisotropic(below, {x, y, z}, face));
            const size_t e =
                mipLevelOffset(n, level, 6) + size_t((z * s + y) * 6 * s + face * s + x);
            for (int c = 0; c < 4; ++c) out.set(e, c, v[c]);
          }
  }
  return out;
}

// The end-to-end oracle: an octree whose leaves hold the dense grid's occupied voxels mips to the
// dense directional pyramid bit for bit on every level it has (mipped as the octree's pools store
// it, in halves), and the shared bounce kernel reads the same cone results through it at every
// leaf.
TEST(SvoLight, OctreeOfADenseGridGivesTheDensePyramidAndConeResults) {
  constexpr int kDepth = 5, kN = 1 << kDepth;
  const DenseTree t = denseTree(kDepth, "mip");
  const Scene& scene = t.scene;
  const BufferSet& dense = t.dense;
  const Buffer& radiance = dense.at(BufferId::vct_light_voxels_radiance);
  const auto& samples = t.samples;
  const Octree& o = t.octree;
  const Leaves& leaves = t.leaves;
  const LeafRadiance& leafRadiance = t.radiance;
  ASSERT_GT(samples.size(), 1000u);

  const NodeLevels mips = cpu::svo::mipTree(o, leaves, leafRadiance, FirstStep::plain);
  const ConeTraceSetup& setup = t.bounce;
  const Buffer stored = storedPyramid(radiance, dense.at(BufferId::vct_mip_radiance_mips6), kN);
  const cpu::ConeVolumes pyramid(radiance, stored, MipMode::anisotropic, kN, setup.lights,
                                 setup.cones);
  const SvoVolumes tree{o, leaves, &leafRadiance, &mips, &leafRadiance, nullptr, &setup.cones};
  for (int level = 1; level < kDepth; ++level) {
    const int s = kN >> level;
    for (int z = 0; z < s; ++z)
      for (int y = 0; y < s; ++y)
        for (int x = 0; x < s; ++x)
          for (int face = 0; face < 6; ++face)
            ASSERT_TRUE(sameBits(tree.pyramidAt(level, face, {x, y, z}),
                                 pyramid.pyramidAt(level, face, {x, y, z})))
                << "level " << level << " voxel " << x << " " << y << " " << z << " face " << face;
  }
  const DenseVolumes denseVolumes{pyramid, radiance, dense.at(BufferId::common_voxelize_albedo),
                                  dense.at(BufferId::common_voxelize_normal), scene.grid};
  size_t gathered = 0;
  for (const auto& sample : samples) {
    const glm::ivec3 v(glm::floor(glm::vec3(sample.position)));
    const glm::vec4 a = shared::bounceVoxel(tree, v, setup.params);
    const glm::vec4 b = shared::bounceVoxel(denseVolumes, v, setup.params);
    ASSERT_TRUE(sameBits(a, b)) << v.x << " " << v.y << " " << v.z;
    gathered += a.x > voxelValue(radiance, v).x;
  }
  EXPECT_GT(gathered, samples.size() / 2);  // the bounce added light, not only passed it on
}

bool sameBits(glm::vec3 a, glm::vec3 b) {
  return sameBits(glm::vec4(a, 0.0f), glm::vec4(b, 0.0f));
}

// The gather in lanes (cpu/cone/gather_lanes.h) gives the bounce kernel's gatherVoxel bit for bit
// on every SIMD level this CPU runs: through the octree's bricks (the svo gather) and through the
// dense pyramid (the vct bounce), for voxels with one normal, with normals that cancel (two
// hemispheres: some leaves' normals zeroed here) and empty voxels.
TEST(SvoLight, TheGatherInLanesIsTheKernelsOnEverySimdLevel) {
  constexpr int kDepth = 4, kN = 1 << kDepth;
  DenseTree t = denseTree(kDepth, "mip");
  std::vector<glm::ivec3> voxels;
  size_t twoSided = 0;
  cpu::svo::forEachRealLeaf(t.octree, [&](size_t slot, glm::ivec3) {
    if (slot % 7 == 3) t.leaves.normal[slot] = glm::vec3(0.0f);
  });
  const tbb::blocked_range<size_t> everyTile(0, t.octree.leafTileCount());
  cpu::svo::forEachRealLeaf(t.octree, everyTile, [&](size_t slot, glm::ivec3 v) {
    voxels.push_back(v);
    twoSided += t.leaves.normal[slot] == glm::vec3(0.0f);
  });
  ASSERT_GT(twoSided, 50u);
  const ConeTraceSetup& setup = t.bounce;
  const Octree& o = t.octree;
  const NodeLevels mips = cpu::svo::mipTree(o, t.leaves, t.radiance, FirstStep::plain);
  const cpu::svo::TreeBricks bricks = cpu::svo::treeBricks(o, t.radiance, mips);
  const SvoVolumes taps{o, t.leaves, &t.radiance, &mips, &t.radiance, nullptr, &setup.cones};
  SvoVolumes tree = taps;
  tree.bricks = &bricks;
  const cpu::cone_lanes::TreeBricks laneBricks = cpu::svo::treeLaneBricks(tree, bricks);
  cpu::cone_lanes::Volumes treeLanes{};
  treeLanes.n = kN;
  treeLanes.bricks = &laneBricks;

  const Buffer& radiance = t.dense.at(BufferId::vct_light_voxels_radiance);
  const cpu::ConeVolumes pyramid(radiance, t.dense.at(BufferId::vct_mip_radiance_mips6),
                                 MipMode::anisotropic, kN, setup.lights, setup.cones);
  const DenseVolumes dense{pyramid, radiance, t.dense.at(BufferId::common_voxelize_albedo),
                           t.dense.at(BufferId::common_voxelize_normal), t.scene.grid};
  std::vector<glm::ivec3> denseVoxels = voxels;
  for (int x = 0; x < kN; x += 3) denseVoxels.emplace_back(x, kN / 2, kN / 2);  // the empty inside

  for (const cpu::SimdLevel level : cpu::runnableSimdLevels()) {
    SCOPED_TRACE(std::string(cpu::simdLevelName(level)));
    std::vector<glm::vec3> lanes(voxels.size());
    cpu::gatherVoxels(level, tree, treeLanes, voxels, setup.params, lanes);
    size_t lit = 0;
    for (size_t i = 0; i < voxels.size(); ++i) {
      const glm::vec3 one = shared::gatherVoxel(taps, voxels[i], setup.params);
      ASSERT_TRUE(sameBits(lanes[i], one)) << "octree, voxel " << i;
      lit += one.x > 0.0f;
    }
    EXPECT_GT(lit, voxels.size() / 2);
    std::vector<glm::vec3> denseLanes(denseVoxels.size());
    cpu::gatherVoxels(level, dense, cpu::laneVolumes(pyramid), denseVoxels, setup.params,
                      denseLanes);
    for (size_t i = 0; i < denseVoxels.size(); ++i)
      ASSERT_TRUE(sameBits(denseLanes[i], shared::gatherVoxel(dense, denseVoxels[i], setup.params)))
          << "dense, voxel " << i;
  }
}

// Progressive bounces [Salm 2015, §4.4.3]: with static light, frame t's radiance is the explicit
// sum of T^j(direct) for j <= t, with T one gather of the previous frame (linear for fixed
// geometry), and the increments shrink geometrically; clearing every frame gives one bounce. The
// pools store halves, so the sum holds to their rounding: each frame rounds the gathered light
// and the radiance (2^-11 each), 2^-8 of the value over the three frames and the sum's terms.
TEST(SvoLight, ProgressiveBouncesAreTheExplicitSumAndConverge) {
  constexpr int kDepth = 4;
  const DenseTree t = denseTree(kDepth, "light_voxels");
  const Octree& o = t.octree;
  const Leaves& leaves = t.leaves;
  const LeafRadiance& direct = t.radiance;
  const size_t slots = direct.size();
  LeafRadiance zero(slots, glm::vec4(0.0f));  // T alone: no direct term, the leaves' opacity
  for (size_t slot = 0; slot < slots; ++slot) zero[slot].a = direct[slot].a;
  const ConeTraceSetup& setup = t.bounce;
  const auto T = [&](const LeafRadiance& x) {
    return cpu::svo::bounceOnce(o, leaves, zero, x, setup.cones, setup.params, FirstStep::plain);
  };
  const LeafRadiance t1 = T(direct), t2 = T(t1), t3 = T(t2);
  const LeafRadiance l3 = cpu::svo::propagateFrames(o, leaves, direct, setup.cones, setup.params, 3,
                                                    false, FirstStep::plain);
  const LeafRadiance once = cpu::svo::propagateFrames(o, leaves, direct, setup.cones, setup.params,
                                                      5, true, FirstStep::plain);
  double d1 = 0, d2 = 0, d3 = 0;
  for (size_t slot = 0; slot < slots; ++slot) {
    if (direct[slot].a <= 0.0f) continue;
    const glm::vec4 sum = direct[slot] + t1[slot] + t2[slot] + t3[slot];
    for (int c = 0; c < 3; ++c) {
      const float rounding = std::ldexp(sum[c], -8) + std::ldexp(1.0f, -24);
      ASSERT_NEAR(l3[slot][c], sum[c], rounding) << slot;
      ASSERT_NEAR(once[slot][c], direct[slot][c] + t1[slot][c], rounding) << slot;
    }
    d1 += t1[slot].x, d2 += t2[slot].x, d3 += t3[slot].x;
  }
  EXPECT_GT(d1, 0.0);
  EXPECT_LT(d2, 0.6 * d1);  // each bounce at most the albedo (0.5 in red) times the previous
  EXPECT_LT(d3, 0.6 * d2);
  EXPECT_GT(d3, 0.0);
}

// The furnace [S14]: a leaf in the cavity of a solid shell where every leaf, the receiver's too,
// sends radiance L with opacity 1. However the mip composits the cavity's rim, every voxel holds
// L x its opacity, so every cone returns L once its opacity saturates (0.999), and the gather
// (cone weights summing to 1, common/cone/cone_sets.h) reflects albedo x L, within 0.1 % (the
// saturation). The NDF-weighted first step [Salm 2015, §4.4.2] weighs each rim child by how its
// normal faces the cone, which at the cavity's edges and corners (one wall's normal each) dims
// what a diagonal cone sees: it is held to 1 % (S14 of docs/svo.md) (it loses 0.9 %).
TEST(SvoLight, FurnaceReflectsAlbedoTimesTheShellsRadiance) {
  constexpr int kDepth = 5, kN = 1 << kDepth;
  const glm::ivec3 receiver(16, 16, 16);
  const glm::vec3 radiance(2.0f, 1.0f, 0.5f), albedo(0.5f, 0.6f, 0.7f);
  std::vector<shared::SvoSample> samples;
  for (int z = 0; z < kN; ++z)
    for (int y = 0; y < kN; ++y)
      for (int x = 0; x < kN; ++x) {
        const glm::ivec3 v(x, y, z), d = glm::abs(v - receiver);
        if (std::max({d.x, d.y, d.z}) > 6 || v == receiver) samples.push_back(cellSample(v));
      }
  const Octree o = cpu::svo::buildOctree(samples, kDepth);
  const size_t slots = o.leafTileCount() * 8;
  Leaves leaves;
  leaves.albedo.assign(slots, glm::vec4(albedo, 1.0f));
  leaves.normal.assign(slots, glm::vec3(0.0f));
  leaves.emission.assign(slots, glm::vec3(0.0f));
  LeafRadiance shell(slots, glm::vec4(0.0f)), direct(slots, glm::vec4(0.0f));
  cpu::svo::forEachRealLeaf(o, [&](size_t slot, glm::ivec3 v) {
    // The shell faces the cavity: its normal is the inward one of the nearest cavity wall.
    const glm::ivec3 d = v - receiver;
    const int axis = std::abs(d.x) >= std::max(std::abs(d.y), std::abs(d.z))
                         ? 0
                         : (std::abs(d.y) >= std::abs(d.z) ? 1 : 2);
    leaves.normal[slot][axis] = v == receiver ? 1.0f : (d[axis] > 0 ? -1.0f : 1.0f);
    shell[slot] = glm::vec4(radiance, 1.0f);
    direct[slot].a = 1.0f;
  });
  const Scene scene = furnace(kN);  // the cone set and parameters of the technique's defaults
  Settings settings;
  settings.vct.mip = MipMode::anisotropic;
  const auto tris = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx(vct(), scene, settings, tris);
  ConeTraceSetup setup = prepareGather(ctx);
  setup.params.topLevel = kDepth - 1;
  for (const FirstStep first : {FirstStep::plain, FirstStep::ndf}) {
    const LeafRadiance out =
        cpu::svo::bounceOnce(o, leaves, direct, shell, setup.cones, setup.params, first);
    bool found = false;
    cpu::svo::forEachRealLeaf(o, [&](size_t slot, glm::ivec3 v) {
      if (v != receiver) return;
      found = true;
      const float tolerance = first == FirstStep::plain ? 1e-3f : 1e-2f;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(out[slot][c], albedo[c] * radiance[c], tolerance * albedo[c] * radiance[c])
            << "channel " << c << (first == FirstStep::ndf ? " (ndf)" : "");
    });
    EXPECT_TRUE(found);
  }
}

// Injection [S17]: samples of a plane at leaf centres under a point light straight above one of
// them: that leaf's radiance is (albedo / pi) E, premultiplied by its clamped opacity; emissive
// samples' premultiplied emission sums to sum of density x r^3 x emission over the samples.
TEST(SvoLight, InjectionIsTheAnalyticDirectLightAndTheSplattedEmission) {
  constexpr int kDepth = 4;
  std::vector<shared::SvoSample> samples;
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) {
      shared::SvoSample s = cellSample({x, 3, z});
      s.albedo = glm::vec3(0.8f, 0.4f, 0.2f);
      s.emission = glm::vec3(0.25f, 0.5f, 1.0f);  // scaled: emissionScale 4 below
      samples.push_back(s);
    }
  const Octree o = cpu::svo::buildOctree(samples, kDepth);
  const Words sums = cpu::svo::accumulateLeaves(o, samples, 65536.0f, "test");
  const Leaves leaves = voxgi::svo::resolveLeaves(sums, 65536.0f, 4.0f);
  glm::dvec3 emitted(0.0);
  for (const glm::vec3& e : leaves.emission) emitted += glm::dvec3(e);
  EXPECT_NEAR(emitted.x, 256 * 1.0, 1e-3);  // 256 samples, density 1, r^3 = 1, emission 1
  EXPECT_NEAR(emitted.z, 256 * 4.0, 1e-3);

  shared::LightData light{};
  light.position = glm::vec3(5.5f, 9.5f, 7.5f);  // 6 leaves above leaf (5, 3, 7)'s centre
  light.intensity = glm::vec3(36.0f);
  light.kind = shared::kLightPoint;
  light.castsShadows = 1u;
  shared::LightVoxelsParams params{};
  params.resolution = 16;
  params.lightCount = 1;
  params.voxelShadow = shared::kVoxelShadowHard;
  params.voxelSize = 1.0f;
  params.shadowOffset = 1.0f;
  const LeafRadiance l = cpu::svo::injectLeaves(o, leaves, {light}, params);
  bool found = false;
  cpu::svo::forEachRealLeaf(o, [&](size_t slot, glm::ivec3 v) {
    if (v != glm::ivec3(5, 3, 7)) return;
    found = true;
    // E = 36 / 6^2 = 1 along the normal; opacity 1. Stored as a half: within half its ULP, 2^-11
    // of the value at most.
    EXPECT_NEAR(l[slot].x, 0.8f / 3.14159265f, 0.8f / 3.14159265f / 2048.0f);
    EXPECT_NEAR(l[slot].z, 0.2f / 3.14159265f, 0.2f / 3.14159265f / 2048.0f);
    EXPECT_EQ(l[slot].a, 1.0f);
  });
  EXPECT_TRUE(found);
}

// Injection's map of the leaves with opacity (opaqueLeaves) answers 0 exactly where looking the
// voxel up in the tree does, on every voxel of the grid, so the visibility rays that skip the
// lookups through it inject the same bits as without it (the kernel's light, rounded to the
// halves the pool stores).
TEST(SvoLight, TheOpaqueLeavesMapIsTheTreesOpacity) {
  constexpr int kDepth = 5, kN = 1 << kDepth;
  const DenseTree t = denseTree(kDepth, "light_voxels");
  const std::vector<uint32_t> opaque = cpu::svo::opaqueLeaves(t.octree, t.leaves);
  ASSERT_EQ(opaque.size(), size_t(1) << (3 * kDepth - 5));  // a bit a leaf
  const SvoVolumes plain{t.octree, t.leaves, nullptr, nullptr, nullptr, nullptr};
  SvoVolumes mapped = plain;
  mapped.opaque = &opaque;
  size_t opaqueVoxels = 0;
  for (int z = 0; z < kN; ++z)
    for (int y = 0; y < kN; ++y)
      for (int x = 0; x < kN; ++x) {
        const float a = plain.opacityAt({x, y, z});
        ASSERT_EQ(std::bit_cast<uint32_t>(mapped.opacityAt({x, y, z})), std::bit_cast<uint32_t>(a));
        opaqueVoxels += a > 0.0f;
      }
  EXPECT_EQ(opaqueVoxels, t.samples.size());

  shared::LightData light{};
  light.position = glm::vec3(10.5f, 20.5f, 12.5f);
  light.intensity = glm::vec3(50.0f);
  light.kind = shared::kLightPoint;
  light.castsShadows = 1u;
  shared::LightVoxelsParams params{};
  params.resolution = kN;
  params.lightCount = 1;
  params.voxelShadow = shared::kVoxelShadowSoft;
  params.shadowKappa = 1.0f;
  params.voxelSize = 1.0f;
  params.shadowOffset = 1.0f;
  const std::vector<shared::LightData> lights{light};
  SvoVolumes volumes = plain;
  volumes.lights = &lights;
  const tbb::blocked_range<size_t> everyTile(0, t.octree.leafTileCount());
  // The visibility rays in every SIMD level's lanes.
  for (const cpu::SimdLevel level : cpu::runnableSimdLevels()) {
    const LeafRadiance injected = cpu::svo::injectLeaves(t.octree, t.leaves, lights, params, level);
    size_t lit = 0;
    cpu::svo::forEachRealLeaf(t.octree, everyTile, [&](size_t slot, glm::ivec3 v) {
      EXPECT_TRUE(
          sameBits(injected[slot], shared::roundToHalf4(shared::lightVoxel(volumes, v, params))))
          << cpu::simdLevelName(level) << " slot " << slot;
      lit += injected[slot].x > 0.0f;
    });
    EXPECT_GT(lit, t.samples.size() / 10);
  }
}

// The closed box of tests/vct/bounce_test.cpp through the octree (S14, S15): every wall emits E
// with albedo rho, its walls sampled into points; the floor's middle leaf after 0 to 3 progressive
// frames obeys the radiosity's bounds, E (1 + rho + ... + rho^N). Measured: 0.78 of the
// exact first bounce (the dense directional pyramid: 0.83), then 0.39 and 0.39 of the one before.
TEST(SvoLight, ClosedBoxApproachesRadiosity) {
  constexpr int kResolution = 32;
  constexpr float kEmission = 1.0f;
  const float rho = 0.5f;
  Material grey;
  grey.albedo = glm::vec3(rho);
  grey.emission = glm::vec3(kEmission);
  Scene scene = closedBox(kResolution, grey);
  scene.camera.width = scene.camera.height = 16;
  const Technique& svo = findTechnique("svo");
  int depth = 0;
  while ((1 << depth) < kResolution) ++depth;
  float l[4];
  for (int frames = 0; frames < 4; ++frames) {
    const Settings settings =
        resolveSettings(svo, {}, scene.file, "default",
                        {"propagate.frames=" + std::to_string(frames), "emitters.mode=voxels"});
    const BufferSet b = runCpuUntil(svo, scene, settings, "propagate");
    const cpu::svo::Octree o = cpu::svo::octreeFromWords(svo::treeWords(b), depth);
    const glm::uvec3 leaf(kResolution / 2, 2, kResolution / 2);
    const uint32_t tile = o.findTile(depth, shared::mortonEncode(leaf >> 1u));
    ASSERT_NE(tile, shared::kSvoNull);
    // Radiance per unit of the leaf's opacity: sampling puts 4 points per leaf face on average,
    // so a leaf's opacity varies about 1 with the points that fall in it.
    const Buffer& r = b.at(BufferId::svo_propagate_radiance);
    const size_t slot = tile * 8 + shared::localId(leaf);
    l[frames] = r.get<float>(slot, 0) / r.get<float>(slot, 3);
  }
  EXPECT_NEAR(l[0], kEmission, 1e-3f);
  EXPECT_GT(l[1] - l[0], rho * kEmission * 0.75f);
  expectFurnaceBounces(l, rho, kEmission);
  std::printf("octree: L0 %.4f L1 %.4f L2 %.4f L3 %.4f (exact 1, 1.5, 1.75, 1.875)\n", l[0], l[1],
              l[2], l[3]);
}

}  // namespace
}  // namespace voxgi::test
