// Light in the octree on the GPU (gpu/svo/propagate.h, mip.h) against the CPU (cpu/svo/propagate.h,
// mip.h) on both GL platforms (the gather on EGL only), with the dense technique's registered
// tolerances for the same kernels (validation/vct/comparisons.inc): injection as light_voxels (bit
// for bit on llvmpipe), the six-face mipmap (plain and NDF-weighted) bit for bit, and one gather as
// bounce: GLSL's division in normalising the leaf normal moves the cones by an ULP (on llvmpipe
// about one value in 200 differs, by 3.5e-7 relative), so max_rel 1e-4.
#include <algorithm>
#include <bit>
#include <cmath>

#include <gtest/gtest.h>

#include "common/svo/stage_inputs.h"
#include "common/lights.h"
#include "common/scene_io/scene_load.h"
#include "common/stage.h"
#include "common/svo/samples.h"
#include "common/cone/cone_trace.h"
#include "common/cone/voxel_light.h"
#include "cpu/svo/mip.h"
#include "cpu/svo/propagate.h"
#include "gpu/svo/mip.h"
#include "gpu/svo/propagate.h"
#include "tests/gl_contexts.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// Index of the first element outside the tolerance, or -1: |gpu - cpu| <= tolerance x the
// element's largest component on either side (validation's max_rel), 0 for bit for bit.
int64_t firstDifference(const std::vector<glm::vec4>& gpu, const std::vector<glm::vec4>& cpu,
                        float tolerance = 0.0f) {
  if (gpu.size() != cpu.size()) return 0;
  for (size_t i = 0; i < gpu.size(); ++i) {
    float magnitude = 0.0f;
    for (int c = 0; c < 4; ++c)
      magnitude = std::max({magnitude, std::abs(gpu[i][c]), std::abs(cpu[i][c])});
    for (int c = 0; c < 4; ++c) {
      const bool same =
          tolerance == 0.0f
              ? std::bit_cast<uint32_t>(gpu[i][c]) == std::bit_cast<uint32_t>(cpu[i][c])
              : std::abs(gpu[i][c] - cpu[i][c]) <= tolerance * magnitude;
      if (!same) return int64_t(i);
    }
  }
  return -1;
}

class GpuSvoLight : public testing::TestWithParam<gpu::GlPlatform> {};

TEST_P(GpuSvoLight, InjectionMipAndGatherAgreeWithTheCpu) {
  constexpr int kDepth = 4;  // 16^3 leaves: the GPU walks the tree per voxel it samples
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  scene.grid.resolution = 1 << kDepth;
  Light light;  // a point light under the ceiling, casting voxel shadows
  light.position = {278.0, 400.0, 280.0};
  light.intensity = glm::vec3(4e4f);
  scene.lights.push_back(light);
  const svo::SampleSet set = svo::prepareSamples(scene, kDepth, 2.0, 1, EmitterLighting::voxels);
  const cpu::svo::Octree o = cpu::svo::buildOctree(set.samples, kDepth);
  const Words sums = cpu::svo::accumulateLeaves(o, set.samples, set.weightScale, scene.file);
  const cpu::svo::Leaves leaves = voxgi::svo::leavesOf(voxgi::svo::leavesBuffer(
      voxgi::svo::resolveLeaves(sums, set.weightScale, set.emissionScale)));
  const svo::OctreeWords words{o.nodes, o.tiles, o.leafTiles, {}};
  const gpu::svo::Tree tree{words, kDepth};
  gpu::GlContext& context = glContext(GetParam());

  Settings settings;
  const auto tris = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx(vct(), scene, settings, tris);
  const std::vector<shared::LightData> lights = voxelLights(scene);
  const shared::LightVoxelsParams lv = lightVoxelsParams(ctx, int(lights.size()), true);
  const cpu::svo::LeafRadiance direct = cpu::svo::injectLeaves(o, leaves, lights, lv);
  EXPECT_EQ(
      firstDifference(gpu::svo::injectLeaves(context, tree, leaves, lights, lv), direct, 1e-5f),
      -1);

  for (const auto first : {cpu::svo::FirstStep::plain, cpu::svo::FirstStep::ndf}) {
    const cpu::svo::NodeLevels cpuMips = cpu::svo::mipTree(o, leaves, direct, first);
    const cpu::svo::NodeLevels gpuMips = gpu::svo::mipTree(context, tree, leaves, direct, first);
    for (int level = 1; level < kDepth; ++level)
      EXPECT_EQ(firstDifference(gpuMips.levels[size_t(level)], cpuMips.levels[size_t(level)]), -1)
          << "level " << level;
  }

  // The gather walks the tree per voxel it samples (most of this test's time on llvmpipe): once,
  // on EGL. Both platforms are llvmpipe here and run the same program; OSMesa's context is
  // checked by the injection and the mipmap above.
  if (GetParam() != gpu::GlPlatform::egl) return;
  ConeTraceSetup bounce = prepareGather(ctx);
  bounce.params.topLevel = kDepth - 1;
  cpu::svo::FrameOutputs cpuFrame, gpuFrame;
  const cpu::svo::LeafRadiance cpuNext =
      cpu::svo::bounceOnce(o, leaves, direct, direct, bounce.cones, bounce.params,
                           cpu::svo::FirstStep::plain, &cpuFrame);
  const cpu::svo::LeafRadiance gpuNext =
      gpu::svo::bounceOnce(context, tree, leaves, direct, direct, bounce.cones, bounce.params,
                           cpu::svo::FirstStep::plain, &gpuFrame);
  EXPECT_EQ(firstDifference(gpuNext, cpuNext, 1e-4f), -1);
  EXPECT_EQ(firstDifference(gpuFrame.gathered, cpuFrame.gathered, 1e-4f), -1);
  size_t lit = 0;
  for (const glm::vec4& g : cpuFrame.gathered) lit += g.x > 0.0f;
  EXPECT_GT(lit, 1000u);  // the gather found light: the comparison is not of zeros
}

INSTANTIATE_TEST_SUITE_P(Platforms, GpuSvoLight,
                         testing::Values(gpu::GlPlatform::osmesa, gpu::GlPlatform::egl),
                         [](const auto& p) { return std::string(gpu::glPlatformName(p.param)); });

}  // namespace
}  // namespace voxgi::test
