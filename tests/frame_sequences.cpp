#include "tests/frame_sequences.h"

#include "common/frame_plan.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

bool runs(const std::vector<FrameStep>& steps, StageId id) {
  for (const FrameStep& s : steps)
    if (s.stage->id == id) return s.runs;
  return false;
}

}  // namespace

size_t smallestMesh(const Scene& scene) {
  size_t best = 0;
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (!scene.meshes[m].triangles.empty() &&
        (scene.meshes[best].triangles.empty() ||
         scene.meshes[m].triangles.size() < scene.meshes[best].triangles.size()))
      best = m;
  return best;
}

std::vector<Scene> motionFrames(const Scene& scene) {
  std::vector<Scene> frames{scene};
  const double voxel = scene.grid.voxelSize();
  frames.push_back(frames.back());
  frames.back().camera.position += glm::dvec3(2.0 * voxel, voxel, 0.0);
  frames.push_back(frames.back());
  frames.push_back(frames.back());
  if (!frames.back().lights.empty()) frames.back().lights[0].position += glm::dvec3(voxel, 0, 0);
  const auto move = [&](size_t mesh, const glm::dvec3& by) {
    frames.push_back(frames.back());
    for (glm::dvec3& p : frames.back().meshes.at(mesh).positions) p += by;
  };
  move(smallestMesh(scene), {0.0, 1.3 * voxel, 0.7 * voxel});
  move(0, {1.3 * voxel, 0.0, 0.0});
  move(smallestMesh(scene), {0.0, -2.1 * voxel, 0.0});
  return frames;
}

void expectIncrementalFramesEqualScratch(const TechniqueCase& c, StageBackend& backend) {
  ASSERT_TRUE(c.error.empty()) << c.error;
  const Technique& technique = findTechnique(c.technique);
  const std::vector<Scene> frames = motionFrames(caseScene(c));
  FrameRunner runner(technique, backend);
  for (size_t f = 0; f < frames.size(); ++f) {
    const Scene& scene = frames[f];
    const Settings settings = caseSettings(c, scene);
    const std::vector<FrameStep>& steps = runner.run(scene, settings);
    const BufferSet& incremental = runner.buffers();
    const SceneChange change = f == 0 ? SceneChange{} : sceneChange(frames[f - 1], scene);
    const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
    const StageContext ctx{technique, scene, settings, triangles};
    BufferSet scratch;
    runPipeline(backend, ctx, scratch);
    ASSERT_EQ(incremental.size(), scratch.size()) << "frame " << f;
    for (const auto& [id, buffer] : scratch)
      EXPECT_TRUE(sameWords(incremental, scratch, id))
          << "frame " << f << " (" << change.describe() << "): " << bufferSpec(id).qualifiedName();
    size_t ran = 0;
    for (const FrameStep& s : steps) ran += s.runs ? 1 : 0;
    switch (f) {
      case 0:
      case 4:
      case 5:
      case 6:
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

}  // namespace voxgi::test
