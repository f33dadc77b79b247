// The diff engine: identical buffers pass, an injected difference fails unless the stage's tie
// classifier calls it a tie, and the voxelize classifier recognises near-boundary voxels.
#include <gtest/gtest.h>

#include "common/voxel_triangles.h"
#include "tests/test_scenes.h"
#include "validation/diff.h"

namespace voxgi::test {
namespace {

const StageSpec& voxelize() {
  return stageSpec(StageId::common_voxelize);
}
EffectPlan plan(const Scene& scene) {
  return vct().plan(scene, Settings{});
}

TEST(Diff, IdenticalBuffersPass) {
  const Scene scene = makeScene(quad(2, 0.3, {0.1, 0.1}, {0.9, 0.9}), unitGrid(16));
  const BufferSet b = runCpu(scene, VoxelizeMode::conservative);
  const auto report = validation::compareStage(voxelize(), plan(scene), b, b, {});
  EXPECT_TRUE(report.pass);
  for (const auto& r : report.buffers) {
    if (r.buffer.starts_with("emission")) {
      EXPECT_NE(r.status, "compared");
    } else {
      EXPECT_EQ(r.differing, 0u);
    }
  }
}

TEST(Diff, InjectedDifferencesFailUnlessTheyAreTies) {
  const Scene scene = makeScene(quad(2, 0.3, {0.1, 0.1}, {0.9, 0.9}), unitGrid(16));
  const BufferSet cpu = runCpu(scene, VoxelizeMode::conservative);
  BufferSet gpu = cpu;
  Buffer weight = gpu.take(BufferId::common_voxelize_weight_sum);
  weight.words[123] += 1;
  gpu.put(std::move(weight));
  Buffer albedo = gpu.take(BufferId::common_voxelize_albedo);
  albedo.set<float>(77, 1, std::nextafter(albedo.get<float>(77, 1), 2.0f));  // 1 ULP: allowed
  gpu.put(std::move(albedo));
  auto noTies = [](size_t) { return false; };
  auto allTies = [](size_t) { return true; };
  const auto failing = validation::compareStage(voxelize(), plan(scene), cpu, gpu, noTies);
  EXPECT_FALSE(failing.pass);
  for (const auto& r : failing.buffers) {
    if (r.buffer == "weight_sum") {
      EXPECT_EQ(r.differing, 1u);
      EXPECT_EQ(r.nonTies, 1u);
      EXPECT_EQ(r.worstElement, 123);
      EXPECT_DOUBLE_EQ(r.maxAbsDiff, 1.0);
    }
    if (r.buffer == "albedo") {
      EXPECT_EQ(r.differing, 0u);
      EXPECT_EQ(r.maxUlp, 1.0);
    }
  }
  // Only the out-of-tolerance voxel is recorded (what the dump's classification grid shows).
  ASSERT_EQ(failing.outside.size(), 1u);
  EXPECT_EQ(failing.outside.at(123), validation::ElementClass::not_a_tie);
  EXPECT_TRUE(validation::compareStage(voxelize(), plan(scene), cpu, gpu, allTies).pass);
  // A voxel differing in several buffers is classified once.
  Buffer albedoSum = gpu.take(BufferId::common_voxelize_albedo_sum);
  albedoSum.words[3 * 123] += 1;
  gpu.put(std::move(albedoSum));
  int calls = 0;
  const auto counted = validation::compareStage(voxelize(), plan(scene), cpu, gpu, [&](size_t) {
    ++calls;
    return true;
  });
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(counted.pass);
  gpu.take(BufferId::common_voxelize_normal);
  EXPECT_FALSE(validation::compareStage(voxelize(), plan(scene), cpu, gpu, allTies).pass);
}

TEST(Diff, VoxelizeTiesAreTheVoxelsOnADecisionBoundary) {
  const double h = 1.0 / 16;
  // A wall exactly on the face between layers 7 and 8: both layers touch it at separation 0.
  const Scene scene =
      makeScene(quad(2, 8.0 * h, {2.3 * h, 2.3 * h}, {13.7 * h, 13.7 * h}), unitGrid(16));
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  Settings settings;
  const auto classify = validation::voxelizeTies(StageContext{vct(), scene, settings, tris});
  EXPECT_TRUE(classify(scene.grid.index({8, 8, 7})));
  EXPECT_TRUE(classify(scene.grid.index({8, 8, 8})));
  EXPECT_FALSE(classify(scene.grid.index({8, 8, 5})));    // far from the wall
  EXPECT_FALSE(classify(scene.grid.index({15, 15, 8})));  // beside it, clearly separated
}

}  // namespace
}  // namespace voxgi::test
