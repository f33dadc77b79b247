// Every stage after voxelize, GPU against the CPU reference (each fed the CPU's inputs), on the
// bundled scenes with each preset, on both GL platforms. Registered comparisons decide.
#include <sstream>

#include <gtest/gtest.h>

#include "common/scene_load.h"
#include "tests/gl_contexts.h"
#include "tests/test_scenes.h"
#include "validation/diff.h"
#include "validation/report.h"

namespace voxgi::test {
namespace {

// Every step of the technique after voxelize (whose own GPU test is tests/gpu_voxelize_test.cpp),
// GPU against CPU through the registered comparisons: each stage must pass.
void expectStagesAgree(const Technique& technique, const Scene& scene, const Settings& settings,
                       gpu::GlPlatform platform) {
  std::vector<std::string> stages;
  for (const StageSpec* s : technique.steps())
    if (s->id != StageId::common_voxelize) stages.push_back(s->qualifiedName());
  const auto reports = diffTechnique(technique, scene, settings, glContext(platform), stages);
  std::ostringstream table;
  validation::printReport(table, reports);
  ASSERT_EQ(reports.size(), stages.size()) << table.str();
  for (const auto& r : reports) EXPECT_TRUE(r.pass) << r.stage << "\n" << table.str();
}

struct Case {
  const char* scene;
  const char* preset;
  gpu::GlPlatform platform;
  std::vector<std::string> sets = {};  // --set assignments after the scene's and the preset's
};

class GpuStages : public testing::TestWithParam<Case> {};

TEST_P(GpuStages, AgreeWithCpu) {
  const Case& c = GetParam();
  Scene scene = loadScene(sourcePath(c.scene));
  scene.grid.resolution = 32;
  scene.camera.width = scene.camera.height = 64;
  const Settings settings = resolveSettings(vct(), scene.settings, scene.file, c.preset, c.sets);
  expectStagesAgree(vct(), scene, settings, c.platform);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, GpuStages,
    testing::Values(
        Case{"scenes/cornell_box.json", "default", gpu::GlPlatform::egl},
        Case{"scenes/bunny.json", "default", gpu::GlPlatform::egl},
        Case{"scenes/bunny.json", "villegas2017", gpu::GlPlatform::egl, {"cones.clearance=0.333"}},
        // The Cornell box asks for a bounce; here the isotropic pyramid bounces too.
        Case{"scenes/bunny.json", "kahl2019", gpu::GlPlatform::osmesa, {"bounce.count=1"}},
        Case{"scenes/cornell_box.json",
             "villegas2017",
             gpu::GlPlatform::osmesa,
             {"cones.clearance=0.5", "cones.offset=1.5", "voxelize.emission=emitters"}}),
    [](const testing::TestParamInfo<Case>& p) {
      std::string name = std::string(p.param.scene).substr(7);
      name = name.substr(0, name.find('.')) + "_" + p.param.preset + "_" +
             gpu::glPlatformName(p.param.platform);
      return name;
    });

// Light propagation volumes, 16^3 and 6 steps (every step's volume compared), both forms and both
// platforms: on the Martin-proportioned Cornell box (its emitter as area lights through the rsm
// stage, or as VPLs of its own), and on the bunny, whose point light goes through the rsm stage
// (or a spot and a sun in its place: one frustum, one box).
struct LpvCase {
  const char* technique;
  gpu::GlPlatform platform;
  std::vector<std::string> sets = {};
  const char* scene = "scenes/cornell_box_lpv.json";
  bool spotAndSun = false;
};

class GpuLpvStages : public testing::TestWithParam<LpvCase> {};

TEST_P(GpuLpvStages, AgreeWithCpu) {
  const LpvCase& c = GetParam();
  const Technique& technique = findTechnique(c.technique);
  Scene scene = loadScene(sourcePath(c.scene));
  scene.grid.resolution = 16;
  scene.camera.width = scene.camera.height = 64;
  if (c.spotAndSun) {
    Light spot = scene.lights.at(0), sun;
    spot.type = Light::Type::spot;
    spot.direction = glm::normalize(glm::dvec3(-0.2, -1.0, -0.3));
    spot.spotAngleDeg = 70.0f;
    sun.type = Light::Type::directional;
    sun.direction = glm::normalize(glm::dvec3(0.4, -1.0, -0.5));
    sun.intensity = glm::vec3(0.5f);
    scene.lights = {spot, sun};
  }
  std::vector<std::string> sets{"propagate.steps=6", "rsm.resolution=64"};
  sets.insert(sets.end(), c.sets.begin(), c.sets.end());
  Settings settings = resolveSettings(technique, scene.settings, scene.file, "default", sets);
  settings.inspect = true;  // as voxgi diff: every step
  expectStagesAgree(technique, scene, settings, c.platform);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, GpuLpvStages,
    testing::Values(
        LpvCase{"lpv", gpu::GlPlatform::egl}, LpvCase{"holpv", gpu::GlPlatform::osmesa},
        LpvCase{"holpv", gpu::GlPlatform::osmesa, {"emitters.mode=voxels"}},
        LpvCase{"holpv",
                gpu::GlPlatform::egl,
                {"propagate.clamp=on", "propagate.accumulate_injection=off", "inject.shift=on"}},
        LpvCase{"holpv", gpu::GlPlatform::egl, {"lpv.storage=f16"}},
        LpvCase{"lpv", gpu::GlPlatform::egl, {}, "scenes/bunny.json"},
        LpvCase{
            "lpv", gpu::GlPlatform::osmesa, {"inject_geometry.blockers=rsm"}, "scenes/bunny.json"},
        LpvCase{"holpv", gpu::GlPlatform::osmesa, {"inject.shift=on"}, "scenes/bunny.json", true}),
    [](const testing::TestParamInfo<LpvCase>& p) {
      std::string scene = std::string(p.param.scene).substr(7);
      return scene.substr(0, scene.find('.')) + "_" + p.param.technique + "_" +
             gpu::glPlatformName(p.param.platform) +
             (p.param.sets.empty() ? "" : "_options" + std::to_string(p.param.sets.size())) +
             (p.param.spotAndSun ? "_spot_sun" : "");
    });

// The sparse voxel octree at 32^3 leaves, every stage, on both platforms: the Cornell box's meshes
// sampled into points (its area light), the bunny (a point light; normal-weighted first step,
// one bounce per frame) and the box as a glossy point cloud (discs in the gbuffer, the specular
// cone through the tree, tricubic shading).
struct SvoCase {
  const char* name;
  gpu::GlPlatform platform;
  std::vector<std::string> sets;
};

class GpuSvoStages : public testing::TestWithParam<SvoCase> {};

TEST_P(GpuSvoStages, AgreeWithCpu) {
  const SvoCase& c = GetParam();
  const std::string name = c.name;
  Scene scene = name == "cloud"   ? cornellBoxCloud(60000, true)
                : name == "bunny" ? loadScene(sourcePath("scenes/bunny.json"))
                                  : loadScene(sourcePath("scenes/cornell_box.json"));
  scene.grid.resolution = 32;
  scene.camera.width = scene.camera.height = 64;
  const Technique& svo = findTechnique("svo");
  const Settings settings = resolveSettings(svo, scene.settings, scene.file, "default", c.sets);
  expectStagesAgree(svo, scene, settings, c.platform);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, GpuSvoStages,
    testing::Values(SvoCase{"cornell_box", gpu::GlPlatform::egl, {"propagate.frames=2"}},
                    SvoCase{"bunny",
                            gpu::GlPlatform::osmesa,
                            {"svo.first_step=ndf", "propagate.clear_each_frame=on",
                             "propagate.frames=2"}},
                    SvoCase{"cloud", gpu::GlPlatform::egl, {"shade.filter=tricubic"}}),
    [](const testing::TestParamInfo<SvoCase>& p) {
      return std::string(p.param.name) + "_" + gpu::glPlatformName(p.param.platform);
    });

}  // namespace
}  // namespace voxgi::test
