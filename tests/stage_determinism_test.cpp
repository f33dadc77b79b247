// Every CPU stage is bit-identical for any thread count and run (docs/architecture.md,
// "Determinism").
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "common/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// Runs every stage of the technique's plan on 1, 2 and 8 threads; the buffers must hash the same.
void expectBitIdenticalOn1_2_8Threads(const Technique& technique, const Scene& scene,
                                      const Settings& settings) {
  const std::string last = technique.steps().back()->qualifiedName();
  uint64_t reference = 0;
  for (int threads : {1, 2, 8}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    tbb::task_arena arena(threads);
    const uint64_t h =
        arena.execute([&] { return hashBuffers(runCpuUntil(technique, scene, settings, last)); });
    if (threads == 1) reference = h;
    EXPECT_EQ(h, reference) << technique.name << " on " << scene.file << ", " << threads
                            << " threads";
  }
}

TEST(StageDeterminism, AllStagesBitIdenticalOn1_2_8Threads) {
  Scene scene = loadScene(sourcePath("scenes/bunny.json"));
  scene.grid.resolution = 32;
  scene.camera.width = scene.camera.height = 48;
  Settings settings;
  applyPreset(settings, vct(), "villegas2017");  // soft voxel shadows: the longest marches
  settings.vct.bounceCount = 1;
  expectBitIdenticalOn1_2_8Threads(vct(), scene, settings);
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
    expectBitIdenticalOn1_2_8Threads(holpv, scene, settings);
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
    expectBitIdenticalOn1_2_8Threads(svo, scene, settings);
  }
}

}  // namespace
}  // namespace voxgi::test
