// GPU voxelize against the CPU reference on both GL platforms: the bundled scenes (at 32^3 the
// textured Cornell box, whose geometry is the plain box's, so textures are diffed with no extra
// case) and the hard cases, every buffer compared with its registered comparison.
#include <sstream>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/scene_io/scene_load.h"
#include "common/voxel_triangles.h"
#include "cpu/stages.h"
#include "gpu/stages.h"
#include "tests/gl_contexts.h"
#include "tests/test_scenes.h"
#include "validation/diff.h"
#include "validation/report.h"

namespace voxgi::test {
namespace {

void expectBackendsAgree(const Scene& scene, VoxelizeMode mode, gpu::GlPlatform platform) {
  Settings settings;
  settings.voxelizeMode = mode;
  const auto reports = diffVct(scene, settings, glContext(platform), {"voxelize"});
  ASSERT_EQ(reports.size(), 1u);
  std::ostringstream table;
  validation::printReport(table, reports);
  EXPECT_TRUE(reports[0].pass) << scene.file << " " << voxelizeModeName(mode) << " on "
                               << gpu::glPlatformName(platform) << "\n"
                               << table.str();
  // On llvmpipe the shared kernel makes the backends bit-identical: no ties are even needed.
  for (const auto& b : reports[0].buffers) EXPECT_EQ(b.differing, 0u) << b.buffer;
}

struct SceneCase {
  const char* file;
  int resolution;
  friend void PrintTo(const SceneCase& c, std::ostream* os) {
    *os << c.file << " at " << c.resolution;
  }
};

std::string testName(
    const testing::TestParamInfo<std::tuple<gpu::GlPlatform, VoxelizeMode, SceneCase>>& param) {
  const SceneCase& sc = std::get<2>(param.param);
  std::string file = sc.file;
  file = file.substr(file.find('/') + 1, file.find('.') - file.find('/') - 1);
  return std::string(gpu::glPlatformName(std::get<0>(param.param))) + "_" +
         voxelizeModeName(std::get<1>(param.param)) + "_" + file + "_" +
         std::to_string(sc.resolution);
}

class GpuVoxelize
    : public testing::TestWithParam<std::tuple<gpu::GlPlatform, VoxelizeMode, SceneCase>> {};

TEST_P(GpuVoxelize, MatchesTheCpuOnTheBundledScenes) {
  const auto& [platform, mode, sc] = GetParam();
  Scene scene = loadScene(sourcePath(sc.file));
  scene.grid.resolution = sc.resolution;
  expectBackendsAgree(scene, mode, platform);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, GpuVoxelize,
    testing::Combine(testing::Values(gpu::GlPlatform::osmesa, gpu::GlPlatform::egl),
                     testing::Values(VoxelizeMode::conservative, VoxelizeMode::antialiased),
                     testing::Values(SceneCase{"scenes/cornell_box_textured.json", 32},
                                     SceneCase{"scenes/cornell_box.json", 64},
                                     SceneCase{"scenes/bunny.json", 32},
                                     SceneCase{"scenes/bunny.json", 64})),
    testName);

// 128^3 on one platform only: the per-buffer work is the same, and it keeps the suite short.
INSTANTIATE_TEST_SUITE_P(Scenes128, GpuVoxelize,
                         testing::Combine(testing::Values(gpu::GlPlatform::egl),
                                          testing::Values(VoxelizeMode::conservative,
                                                          VoxelizeMode::antialiased),
                                          testing::Values(SceneCase{"scenes/cornell_box.json", 128},
                                                          SceneCase{"scenes/bunny.json", 128})),
                         testName);

TEST(GpuVoxelizeHardCases, AgreeWithTheCpu) {
  const double h = 1.0 / 16;
  std::vector<Triangle> degenerate = quad(2, 0.5, {0.1, 0.1}, {0.9, 0.9});
  degenerate.push_back({glm::dvec3(0.2), glm::dvec3(0.2), glm::dvec3(0.2)});
  degenerate.push_back({glm::dvec3(0.1), glm::dvec3(0.5), glm::dvec3(0.9)});
  std::vector<Triangle> far = {
      {glm::dvec3(0.11, 0.2, 0.3), glm::dvec3(0.83, 0.35, 0.6), glm::dvec3(0.4, 0.9, 0.75)}};
  for (auto& p : far[0]) p += glm::dvec3(1e6);
  GridSpec farGrid = unitGrid(32);
  farGrid.min += glm::dvec3(1e6);
  const std::vector<std::pair<const char*, Scene>> cases = {
      {"degenerate", makeScene(degenerate, unitGrid(16))},
      {"wall on a voxel face",
       makeScene(quad(2, 8.0 * h, {2 * h, 2 * h}, {14 * h, 14 * h}), unitGrid(16))},
      {"wall moved 1e-4 voxel",
       makeScene(quad(2, (8.0 + 1e-4) * h, {2 * h, 2 * h}, {14 * h, 14 * h}), unitGrid(16))},
      {"larger than the grid", makeScene(quad(0, 0.53, {-100, -100}, {100, 100}), unitGrid(16))},
      {"far from the origin", makeScene(far, farGrid)},
      {"tiny", makeScene({{glm::dvec3(1e-5, 2e-5, 3e-5), glm::dvec3(8e-5, 3e-5, 6e-5),
                           glm::dvec3(4e-5, 9e-5, 7e-5)}},
                         unitGrid(32, 1e-4))},
      {"empty", makeScene({}, unitGrid(16))},
      {"resolution 1", makeScene(quad(1, 0.5, {0.25, 0.25}, {0.75, 0.75}), unitGrid(1))},
  };
  for (const auto& [label, scene] : cases)
    for (VoxelizeMode mode : {VoxelizeMode::conservative, VoxelizeMode::antialiased}) {
      SCOPED_TRACE(label);
      expectBackendsAgree(scene, mode, gpu::GlPlatform::egl);
    }
}

TEST(GpuVoxelizeHardCases, ResolutionBeyondTheGlLimitIsAnInputError) {
  gpu::GlContext& context = glContext(gpu::GlPlatform::egl);
  int n = 1;
  while (3 * n <= context.max3dTextureSize()) n *= 2;
  Scene scene = makeScene(quad(2, 0.5, {0.1, 0.1}, {0.9, 0.9}), unitGrid(n));
  Settings settings;
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  BufferSet out;
  EXPECT_THROW(gpu::common::voxelize(context, StageContext{vct(), scene, settings, tris}, out),
               InputError);
}

}  // namespace
}  // namespace voxgi::test
