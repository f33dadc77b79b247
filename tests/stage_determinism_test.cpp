// Every CPU stage is bit-identical for any thread count and run (docs/architecture.md,
// "Determinism").
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "common/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

TEST(StageDeterminism, AllStagesBitIdenticalOn1_2_8Threads) {
  Scene scene = loadScene(sourcePath("scenes/bunny.json"));
  scene.grid.resolution = 32;
  scene.camera.width = scene.camera.height = 48;
  Settings settings;
  applyPreset(settings, vct(), "villegas2017");  // soft voxel shadows: the longest marches
  settings.vct.bounceCount = 1;
  const std::string last = vct().steps().back()->qualifiedName();
  uint64_t reference = 0;
  for (int threads : {1, 2, 8}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    tbb::task_arena arena(threads);
    const uint64_t h =
        arena.execute([&] { return hashBuffers(runCpuUntil(scene, settings, last)); });
    if (threads == 1) reference = h;
    EXPECT_EQ(h, reference) << threads << " threads";
  }
}

// holpv with clamp and every step kept, on the Martin-proportioned Cornell box (an area light)
// and on the bunny (a point light through the rsm stage, and its ceiling panel).
TEST(StageDeterminism, LpvBitIdenticalOn1_2_8Threads) {
  for (const char* file : {"scenes/cornell_box_lpv.json", "scenes/bunny.json"}) {
    Scene scene = loadScene(sourcePath(file));
    scene.grid.resolution = 16;
    scene.camera.width = scene.camera.height = 48;
    const Technique& holpv = findTechnique("holpv");
    Settings settings =
        resolveSettings(holpv, scene.settings, scene.file, "default",
                        {"propagate.steps=5", "propagate.clamp=on", "rsm.resolution=32"});
    settings.inspect = true;
    const std::string last = holpv.steps().back()->qualifiedName();
    uint64_t reference = 0;
    for (int threads : {1, 2, 8}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
      tbb::task_arena arena(threads);
      const uint64_t h =
          arena.execute([&] { return hashBuffers(runCpuUntil(holpv, scene, settings, last)); });
      if (threads == 1) reference = h;
      EXPECT_EQ(h, reference) << file << ", " << threads << " threads";
    }
  }
}

// The octree with two progressive frames and the normal-weighted first step, from the meshes of
// the bunny (a point light) and a glossy point cloud with the Cornell box's area light.
TEST(StageDeterminism, SvoBitIdenticalOn1_2_8Threads) {
  Scene bunny = loadScene(sourcePath("scenes/bunny.json"));
  for (Scene scene : {bunny, cornellBoxCloud(60000, true)}) {
    scene.grid.resolution = 32;
    scene.camera.width = scene.camera.height = 48;
    const Technique& svo = findTechnique("svo");
    const Settings settings = resolveSettings(svo, scene.settings, scene.file, "default",
                                              {"propagate.frames=2", "svo.first_step=ndf"});
    const std::string last = svo.steps().back()->qualifiedName();
    uint64_t reference = 0;
    for (int threads : {1, 2, 8}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
      tbb::task_arena arena(threads);
      const uint64_t h =
          arena.execute([&] { return hashBuffers(runCpuUntil(svo, scene, settings, last)); });
      if (threads == 1) reference = h;
      EXPECT_EQ(h, reference) << scene.file << ", " << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace voxgi::test
