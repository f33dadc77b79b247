// lpv/propagate as the CPU backend runs it (SIMD lanes on the widest instruction set, rows over
// threads, the lanes' layout, f16 rounding, history): every step's volume and the accumulated one
// are, bit for bit, the shared kernel applied cell by cell to the injected volume, step after
// step, as the stage's definition says (docs/stages/lpv/propagate.md). The kernel's own
// properties are propagate_kernel_test.cpp's.
#include <cstring>

#include <gtest/gtest.h>

#include "common/lpv/inject.h"
#include "common/lpv/propagate.h"
#include "common/lpv/sh_buffers.h"
#include "common/scene_io/scene_load.h"
#include "common/voxelize_update.h"
#include "shaders/shared/lpv/propagate_kernel.h"
#include "tests/lpv/kernel_volumes.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

struct StageCase {
  const char* technique;
  std::vector<std::string> sets;
};

void PrintTo(const StageCase& c, std::ostream* os) {
  *os << c.technique;
  for (const std::string& s : c.sets) *os << " " << s;
}

class PropagateStage : public testing::TestWithParam<StageCase> {};

TEST_P(PropagateStage, IsTheKernelStepByStep) {
  Scene scene = loadScene(sourcePath("scenes/cornell_box_lpv.json"));
  scene.grid.resolution = 16;
  scene.camera.width = scene.camera.height = 16;
  const Technique& technique = findTechnique(GetParam().technique);
  std::vector<std::string> sets = GetParam().sets;
  sets.push_back("propagate.history=on");
  const Settings settings = resolveSettings(technique, scene.settings, scene.file, "default", sets);
  const BufferSet got = runCpuUntil(technique, scene, settings, "propagate");

  const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx{technique, scene, settings, triangles};
  const LpvSettings& s = settings.lpv;
  const lpv::ShBuffers sh = lpv::shBuffers(s);
  const int n = 16, C = s.coefficients();
  lpv::Propagation setup = lpv::preparePropagation(s, n);
  std::vector<float> volume = lpv::injectedVolume(ctx, got.at(sh.intensitySum));
  lpv::prepareStorage(s, setup.params, volume);
  std::vector<float> accumulated =
      s.accumulateInjection == LpvToggle::on ? volume : std::vector<float>(volume.size(), 0.0f);
  std::vector<glm::vec4> blocking;  // without occlusion inject_geometry does not run
  if (const Buffer* b = got.find(BufferId::lpv_inject_geometry_blocking)) {
    blocking.resize(b->elementCount());
    std::memcpy(blocking.data(), b->words.data(), blocking.size() * sizeof(glm::vec4));
  }

  const Buffer& steps = got.at(sh.steps);
  const auto expectStep = [&](int k) {
    const size_t words = volume.size();
    ASSERT_EQ(std::memcmp(steps.words.data() + size_t(k) * words, volume.data(), words * 4), 0)
        << "step " << k << "'s volume";
  };
  expectStep(0);
  ASSERT_GE(setup.steps, 2);
  for (int step = 1; step <= setup.steps; ++step) {
    std::vector<float> next(volume.size());
    shared::PropagateParams params = setup.params;
    params.occlude = lpv::occludedStep(s, step) ? 1 : 0;
    const KernelVolumes kernel{setup.entries, volume, &blocking, next, &accumulated, params, n, C};
    for (int z = 0; z < n; ++z)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) shared::propagateCell(kernel, glm::ivec3(x, y, z), params);
    volume = std::move(next);
    expectStep(step);
  }
  const Buffer& sum = got.at(sh.accumulated);
  ASSERT_EQ(sum.words.size(), accumulated.size());
  EXPECT_EQ(std::memcmp(sum.words.data(), accumulated.data(), accumulated.size() * 4), 0);
}

INSTANTIATE_TEST_SUITE_P(
    Options, PropagateStage,
    testing::Values(StageCase{"lpv", {}}, StageCase{"holpv", {}},
                    StageCase{"lpv", {"propagate.directions=26", "propagate.clamp=on"}},
                    StageCase{"holpv", {"lpv.storage=f16", "propagate.directions=6"}},
                    StageCase{"lpv",
                              {"propagate.occlusion=off", "propagate.accumulate_injection=off",
                               "lpv.storage=f16"}}));

}  // namespace
}  // namespace voxgi::test
