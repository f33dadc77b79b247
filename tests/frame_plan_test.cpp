// The planner in time (common/frame_plan.h): on each technique's "motion" case
// (tests/cases/<technique>.json), a sequence in which the camera moves, nothing moves, a light
// moves and a mesh moves; every frame reached incrementally (the stages frameSteps runs, the rest
// reused) equals the frame rendered from scratch bit for bit on the CPU, and the steps reuse what
// the change allows: no volume stage when only the camera moved, nothing when nothing did, and
// no voxelization when only a light did.
#include <gtest/gtest.h>

#include "common/frame_plan.h"
#include "common/scene/scene_load.h"
#include "cpu/backend.h"
#include "tests/technique_cases.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// Frame 0 the case's scene; 1 the camera moved; 2 the same; 3 the first light moved; 4 the first
// mesh moved (by about a voxel).
std::vector<Scene> motionFrames(const Scene& scene) {
  std::vector<Scene> frames{scene};
  const double voxel = scene.grid.voxelSize();
  frames.push_back(frames.back());
  frames.back().camera.position += glm::dvec3(2.0 * voxel, voxel, 0.0);
  frames.push_back(frames.back());
  frames.push_back(frames.back());
  if (!frames.back().lights.empty()) frames.back().lights[0].position += glm::dvec3(voxel, 0, 0);
  frames.push_back(frames.back());
  for (glm::dvec3& p : frames.back().meshes.at(0).positions) p += glm::dvec3(1.3 * voxel, 0, 0);
  return frames;
}

bool runs(const std::vector<FrameStep>& steps, StageId id) {
  for (const FrameStep& s : steps)
    if (s.stage->id == id) return s.runs;
  return false;
}

class FramePlan : public testing::TestWithParam<TechniqueCase> {};

TEST_P(FramePlan, IncrementalFramesEqualFramesFromScratch) {
  const TechniqueCase& c = GetParam();
  ASSERT_TRUE(c.error.empty()) << c.error;
  const Technique& technique = findTechnique(c.technique);
  const std::vector<Scene> frames = motionFrames(caseScene(c));
  cpu::CpuBackend cpu;
  BufferSet incremental;
  std::optional<EffectPlan> previous;
  for (size_t f = 0; f < frames.size(); ++f) {
    const Scene& scene = frames[f];
    const Settings settings = caseSettings(c, scene);
    const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
    const StageContext ctx{technique, scene, settings, triangles};
    const SceneChange change = f == 0 ? SceneChange{} : sceneChange(frames[f - 1], scene);
    const std::vector<FrameStep> steps =
        frameSteps(ctx, previous ? &*previous : nullptr, change);
    runFrame(cpu, ctx, incremental, steps);
    previous = ctx.plan;
    BufferSet scratch;
    runPipeline(cpu, ctx, scratch);
    ASSERT_EQ(incremental.size(), scratch.size()) << "frame " << f;
    for (const auto& [id, buffer] : scratch)
      EXPECT_TRUE(sameWords(incremental, scratch, id)) << "frame " << f << " (" << change.describe()
                                                       << "): " << bufferSpec(id).qualifiedName();
    size_t ran = 0;
    for (const FrameStep& s : steps) ran += s.runs ? 1 : 0;
    switch (f) {
      case 0:
      case 4:
        EXPECT_EQ(ran, steps.size()) << "frame " << f;
        break;
      case 1:  // the camera: the stages before the first that reads it are reused
        for (const FrameStep& s : steps) {
          if (stageSceneInputs(s.stage->id) & kSceneCamera) break;
          EXPECT_FALSE(s.runs) << s.stage->qualifiedName() << ": " << s.why;
        }
        EXPECT_FALSE(runs(steps, StageId::common_voxelize));
        EXPECT_TRUE(runs(steps, StageId::common_gbuffer));
        break;
      case 2:
        EXPECT_EQ(ran, 0u);
        break;
      case 3:
        EXPECT_FALSE(runs(steps, StageId::common_voxelize));
        EXPECT_GT(ran, 0u);
        break;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Techniques, FramePlan, testing::ValuesIn(allTechniqueCases("motion")),
                         [](const testing::TestParamInfo<TechniqueCase>& p) {
                           return p.param.label;
                         });

// What moved, as the plan says it.
TEST(FramePlan, SceneChangeSaysWhatMoved) {
  const Scene a = loadScene(sourcePath("scenes/bunny.json"));
  EXPECT_EQ(sceneChange(a, a).parts, 0u);
  EXPECT_EQ(sceneChange(a, a).describe(), "nothing moved");
  Scene b = a;
  b.camera.lookAt.x += 1.0;
  b.lights[0].intensity *= 2.0f;
  b.meshes[0].positions[0].y += 1e-9;
  const SceneChange c = sceneChange(a, b);
  EXPECT_EQ(c.parts, unsigned(kSceneGeometry | kSceneLights | kSceneCamera));
  size_t all = 0;
  for (const Mesh& m : a.meshes) all += m.triangles.size();
  const size_t bunny = a.meshes[0].triangles.size();
  EXPECT_EQ(c.describe(), "1 mesh moved: " + std::to_string(bunny) + " of " + std::to_string(all) +
                              " triangles (" +
                              std::to_string(int(std::lround(100.0 * double(bunny) / double(all)))) +
                              " %); 1 light changed; the camera moved");
}

}  // namespace
}  // namespace voxgi::test
