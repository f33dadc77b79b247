// The voxelize hard cases of docs/stages/voxelize.md, on the CPU reference (the GPU twin runs the
// same cases in gpu_voxelize_test.cpp).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/scene_io/scene_load.h"
#include "common/voxel_triangles.h"
#include "cpu/stages.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

size_t occupied(const BufferSet& b) {
  size_t n = 0;
  for (uint32_t w : b.at(BufferId::common_voxelize_weight_sum).words) n += w != 0u;
  return n;
}

TEST(VoxelizeHardCases, DegenerateTrianglesContributeNothing) {
  const glm::dvec3 a(0.2, 0.3, 0.4), b(0.7, 0.3, 0.4), c(0.45, 0.3, 0.4);
  const auto valid = quad(2, 0.5, {0.1, 0.1}, {0.9, 0.9});
  std::vector<Triangle> withDegenerate = valid;
  withDegenerate.push_back({a, a, a});  // repeated vertices
  withDegenerate.push_back({a, b, c});  // collinear
  withDegenerate.push_back({a, b, b});  // zero area
  const Scene clean = makeScene(valid, unitGrid(16));
  const Scene dirty = makeScene(withDegenerate, unitGrid(16));
  EXPECT_EQ(prepareVoxelTriangles(dirty, dirty.grid).degenerate, 3u);
  for (VoxelizeMode mode : {VoxelizeMode::conservative, VoxelizeMode::antialiased})
    EXPECT_EQ(hashBuffers(runCpu(dirty, mode)), hashBuffers(runCpu(clean, mode)));
}

TEST(VoxelizeHardCases, NonFiniteVerticesAreAnInputError) {
  Scene scene = makeScene(quad(2, 0.5, {0.1, 0.1}, {0.9, 0.9}), unitGrid(16));
  scene.meshes[0].positions[1].y = std::nan("");
  try {
    validateGeometry(scene);
    FAIL() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 1"), std::string::npos) << e.what();
  }
  const std::string path = testTempDir() + "inf.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n";
  EXPECT_THROW(loadScene(path), InputError);
}

TEST(VoxelizeHardCases, WallOnAVoxelFaceAndMovedByATenThousandthOfAVoxel) {
  const double h = 1.0 / 16;
  auto wallAt = [&](double z) {
    return makeScene(quad(2, z * h, {2.0 * h, 2.0 * h}, {14.0 * h, 14.0 * h}), unitGrid(16));
  };
  // Conservative, documented: a wall exactly on the face between layers 7 and 8 lies in both
  // closed voxels and fills both with its full area; moved by 1e-4 voxel it fills one layer.
  const BufferSet onFace = runCpu(wallAt(8.0), VoxelizeMode::conservative);
  const BufferSet moved = runCpu(wallAt(8.0 + 1e-4), VoxelizeMode::conservative);
  const GridSpec g = unitGrid(16);
  EXPECT_NEAR(onFace.at(BufferId::common_voxelize_weight_sum).words[g.index({8, 8, 7})], 65536.0,
              2.0);
  EXPECT_NEAR(onFace.at(BufferId::common_voxelize_weight_sum).words[g.index({8, 8, 8})], 65536.0,
              2.0);
  EXPECT_EQ(moved.at(BufferId::common_voxelize_weight_sum).words[g.index({8, 8, 7})], 0u);
  EXPECT_NEAR(moved.at(BufferId::common_voxelize_weight_sum).words[g.index({8, 8, 8})], 65536.0,
              2.0);
  // Antialiased: every voxel changes by O(1e-4) (opacity and premultiplied attributes).
  for (double z : {8.0, 8.5, 8.37}) {
    const BufferSet a = runCpu(wallAt(z), VoxelizeMode::antialiased);
    const BufferSet b = runCpu(wallAt(z + 1e-4), VoxelizeMode::antialiased);
    double worst = 0.0;
    for (size_t e = 0; e < g.voxelCount(); ++e) {
      const double oa = a.at(BufferId::common_voxelize_opacity).get<float>(e, 0),
                   ob = b.at(BufferId::common_voxelize_opacity).get<float>(e, 0);
      worst = std::max(worst, std::abs(oa - ob));
      for (int c = 0; c < 3; ++c)
        worst =
            std::max(worst, std::abs(oa * a.at(BufferId::common_voxelize_albedo).get<float>(e, c) -
                                     ob * b.at(BufferId::common_voxelize_albedo).get<float>(e, c)));
    }
    // The tent weight moves by 1e-4 per 1e-4 voxel; rounding to 2^-16 adds a few units.
    EXPECT_LT(worst, 1e-4 + 8.0 / 65536.0) << "wall at " << z;
    EXPECT_GT(worst, 0.0) << "wall at " << z << " did not move at all";
  }
}

TEST(VoxelizeHardCases, TriangleLargerThanTheGrid) {
  const Scene scene = makeScene(quad(2, 0.53, {-100.0, -100.0}, {100.0, 100.0}), unitGrid(16));
  EXPECT_EQ(prepareVoxelTriangles(scene, scene.grid).clipped, 2u);
  for (VoxelizeMode mode : {VoxelizeMode::conservative, VoxelizeMode::antialiased}) {
    const BufferSet b = runCpu(scene, mode);
    const GridSpec& g = scene.grid;
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const float opacity =
            b.at(BufferId::common_voxelize_opacity).get<float>(g.index({i, j, 8}), 0);
        EXPECT_GT(opacity, mode == VoxelizeMode::conservative ? 0.99f : 0.45f) << i << "," << j;
      }
    if (mode == VoxelizeMode::conservative) {
      EXPECT_EQ(occupied(b), 256u);
    }
  }
}

TEST(VoxelizeHardCases, SceneFarFromTheOriginMatchesTheSameSceneAtTheOrigin) {
  auto shifted = [](double offset) {
    std::vector<Triangle> tris = {
        {glm::dvec3(0.11, 0.2, 0.3), glm::dvec3(0.83, 0.35, 0.6), glm::dvec3(0.4, 0.9, 0.75)}};
    for (auto& t : tris)
      for (auto& p : t) p += glm::dvec3(offset);
    GridSpec g = unitGrid(32);
    g.min += glm::dvec3(offset);
    return makeScene(tris, g);
  };
  for (VoxelizeMode mode : {VoxelizeMode::conservative, VoxelizeMode::antialiased}) {
    const BufferSet near = runCpu(shifted(0.0), mode), far = runCpu(shifted(1e6), mode);
    const auto& a = near.at(BufferId::common_voxelize_weight_sum).words;
    const auto& b = far.at(BufferId::common_voxelize_weight_sum).words;
    for (size_t e = 0; e < a.size(); ++e)
      ASSERT_NEAR(double(a[e]), double(b[e]), 2.0 + 1e-4 * a[e])
          << voxelizeModeName(mode) << " voxel " << e;
  }
}

TEST(VoxelizeHardCases, TinySceneVoxelizesLikeTheUnitScene) {
  auto scaled = [](double s) {
    std::vector<Triangle> tris = {{glm::dvec3(0.11, 0.2, 0.3) * s, glm::dvec3(0.83, 0.35, 0.6) * s,
                                   glm::dvec3(0.4, 0.9, 0.75) * s}};
    return makeScene(tris, unitGrid(32, s));
  };
  const BufferSet unit = runCpu(scaled(1.0), VoxelizeMode::conservative);
  const BufferSet tiny = runCpu(scaled(1e-4), VoxelizeMode::conservative);
  EXPECT_EQ(occupied(unit), occupied(tiny));
  const auto& a = unit.at(BufferId::common_voxelize_weight_sum).words;
  const auto& b = tiny.at(BufferId::common_voxelize_weight_sum).words;
  for (size_t e = 0; e < a.size(); ++e) ASSERT_NEAR(double(a[e]), double(b[e]), 2.0 + 1e-4 * a[e]);
}

TEST(VoxelizeHardCases, EmptySceneGivesEmptyVolumes) {
  Scene scene = makeScene({}, unitGrid(16));
  for (VoxelizeMode mode : {VoxelizeMode::conservative, VoxelizeMode::antialiased}) {
    const BufferSet b = runCpu(scene, mode);
    EXPECT_EQ(occupied(b), 0u);
  }
  Scene none;
  none.file = "empty";
  const GridSpec fitted = fitGrid(none.bounds(), 8);
  EXPECT_GT(fitted.size, 0.0);
}

TEST(VoxelizeHardCases, ResolutionOne) {
  const Scene scene = makeScene(quad(2, 0.5, {0.25, 0.25}, {0.75, 0.75}), unitGrid(1));
  const BufferSet b = runCpu(scene, VoxelizeMode::conservative);
  EXPECT_NEAR(b.at(BufferId::common_voxelize_weight_sum).words[0], 0.25 * 65536.0, 2.0);
  EXPECT_NO_THROW(runCpu(scene, VoxelizeMode::antialiased));
}

TEST(VoxelizeHardCases, ResolutionTooLargeForMemoryIsAnErrorBeforeAllocating) {
  Scene scene = makeScene(quad(2, 0.5, {0.25, 0.25}, {0.75, 0.75}), unitGrid(2048));
  scene.lights.push_back(testLight());  // so that the plan voxelizes (EffectPlan::dark)
  try {
    const Settings settings;
    const VoxelTriangles none{};
    checkStageMemory(StageContext{vct(), scene, settings, none}, StageId::common_voxelize);
    FAIL() << "2048^3 voxelize buffers accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grid.resolution"), std::string::npos) << e.what();
  }
  EXPECT_THROW(runCpu(scene, VoxelizeMode::conservative), InputError);
  EXPECT_THROW(readResolution("s.json", "grid.resolution", 4096), InputError);
  EXPECT_THROW(readResolution("s.json", "grid.resolution", 100), InputError);
  EXPECT_THROW(readResolution("s.json", "grid.resolution", 0), InputError);
}

}  // namespace
}  // namespace voxgi::test
