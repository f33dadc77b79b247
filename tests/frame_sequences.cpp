#include "tests/frame_sequences.h"

#include "common/frame_plan.h"
#include "common/voxelize_update.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

bool runs(const std::vector<FrameStep>& steps, StageId id) {
  for (const FrameStep& s : steps)
    if (s.stage->id == id) return s.runs;
  return false;
}

// A floor at y = 0.27 (voxel layer 4 of 16) under a point light, and a blocker square at y = 0.6 in
// a mesh of its own, moved by `shift` along x.
Scene floorAndBlocker(double shift) {
  Scene scene = makeScene(quad(1, 0.27, {0.0, 0.0}, {1.0, 1.0}), unitGrid(16));
  Scene blocker = makeScene(quad(1, 0.6, {0.3 + shift, 0.35}, {0.55 + shift, 0.6}), unitGrid(16));
  scene.meshes.push_back(blocker.meshes.at(0));
  // Both quads face the light (+y).
  for (Mesh& m : scene.meshes)
    for (auto& t : m.triangles) {
      const glm::dvec3 e1 = m.positions[t.y] - m.positions[t.x];
      const glm::dvec3 e2 = m.positions[t.z] - m.positions[t.x];
      if (glm::cross(e1, e2).y < 0.0) std::swap(t.y, t.z);
    }
  Light light;
  light.position = {0.5, 0.95, 0.5};
  light.intensity = glm::vec3(2.0f);
  scene.lights = {light};
  return withCamera(scene, {0.5, 0.8, 1.6}, {0.5, 0.3, 0.5}, {0, 1, 0}, 50.0, 32);
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
  move(smallestMesh(scene), {0.0, -10.1 * voxel, 0.0});
  return frames;
}

void expectIncrementalFramesEqualScratch(const TechniqueCase& c, StageBackend& backend) {
  ASSERT_TRUE(c.error.empty()) << c.error;
  const Technique& technique = findTechnique(c.technique);
  const std::vector<Scene> frames = motionFrames(caseScene(c));
  FrameRunner runner(technique, backend);
  for (size_t f = 0; f < frames.size(); ++f) {
    const Scene& scene = frames[f];
    // The plan of a sequence's frames (FrameRunner sets it), so that voxelize's sums, which the
    // next frame's update starts from, are compared too.
    Settings settings = caseSettings(c, scene);
    settings.sequence = true;
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
          if (stageSceneInputs(s.stage->id) & stage_reads::camera) break;
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

void expectVolumesUpdateEveryInterval(const TechniqueCase& c, StageBackend& backend, int interval) {
  ASSERT_TRUE(c.error.empty()) << c.error;
  const Technique& technique = findTechnique(c.technique);
  const std::vector<Scene> frames = motionFrames(caseScene(c));
  const auto settingsOf = [&](const Scene& scene) {
    Settings s = caseSettings(c, scene);
    s.updateInterval = interval;
    s.sequence = true;  // the plan of a sequence's frames, as FrameRunner sets it
    return s;
  };
  FrameRunner runner(technique, backend);
  for (size_t f = 0; f < frames.size(); ++f) {
    const std::vector<FrameStep>& steps = runner.run(frames[f], settingsOf(frames[f]));
    const size_t update = f - f % size_t(interval);
    const Scene& scene = frames[f];
    const Settings settings = settingsOf(scene), volumeSettings = settingsOf(frames[update]);
    const VoxelTriangles triangles = prepareVoxelTriangles(scene, scene.grid);
    const VoxelTriangles volumeTriangles = prepareVoxelTriangles(frames[update], scene.grid);
    const StageContext ctx{technique, scene, settings, triangles};
    const StageContext volumeCtx{technique, frames[update], volumeSettings, volumeTriangles};
    BufferSet scratch;
    bool volume = true;  // before the first stage that reads the camera
    for (const StageSpec* stage : plannedStages(ctx)) {
      volume = volume && (stageSceneInputs(stage->id) & stage_reads::camera) == 0;
      ASSERT_TRUE(runStage(backend, *stage, volume ? volumeCtx : ctx, scratch).ok());
      for (const FrameStep& s : steps) {
        if (s.stage == stage && volume && f != update) {
          EXPECT_FALSE(s.runs) << "frame " << f << ": " << stage->qualifiedName() << ": " << s.why;
        }
      }
    }
    ASSERT_EQ(runner.buffers().size(), scratch.size()) << "frame " << f;
    for (const auto& [id, buffer] : scratch)
      EXPECT_TRUE(sameWords(runner.buffers(), id, scratch, id))
          << "frame " << f << " (volumes of frame " << update
          << "): " << bufferSpec(id).qualifiedName();
  }
}

void expectCarriedFramesEqualScratch(TechniqueCase c, StageBackend& backend) {
  ASSERT_TRUE(c.error.empty()) << c.error;
  const Technique& technique = findTechnique(c.technique);
  c.resolution = 16;  // two runners through seven frames: the smallest tree that moves
  c.image = 24;
  const std::vector<Scene> frames = motionFrames(caseScene(c));
  FrameRunner incremental(technique, backend), scratch(technique, backend, true);
  for (size_t f = 0; f < frames.size(); ++f) {
    Settings settings = caseSettings(c, frames[f]);
    settings.svo.carry = SvoToggle::on;
    const std::vector<FrameStep>& steps = incremental.run(frames[f], settings);
    scratch.run(frames[f], settings);
    EXPECT_TRUE(runs(steps, StageId::svo_propagate)) << "frame " << f;
    if (f == 2) {
      EXPECT_FALSE(runs(steps, StageId::svo_build)) << "nothing moved in frame 2";
    }
    ASSERT_EQ(incremental.buffers().size(), scratch.buffers().size()) << "frame " << f;
    for (const auto& [id, buffer] : scratch.buffers())
      EXPECT_TRUE(sameWords(incremental.buffers(), scratch.buffers(), id))
          << "frame " << f << ": " << bufferSpec(id).qualifiedName();
  }
}

void expectPartialRelightEqualsScratch(StageBackend& backend) {
  const Technique& technique = findTechnique("vct");
  Settings settings;
  settings.vct.voxelShadow = VoxelShadow::hard;
  const Scene before = floorAndBlocker(0.0), now = floorAndBlocker(2.0 / 16.0);
  FrameRunner runner(technique, backend);
  runner.run(before, settings);
  runner.run(now, settings);
  const VoxelTriangles trianglesBefore = prepareVoxelTriangles(before, before.grid);
  const VoxelTriangles trianglesNow = prepareVoxelTriangles(now, now.grid);
  BufferSet scratchBefore, scratch;
  runPipeline(backend, StageContext{technique, before, settings, trianglesBefore}, scratchBefore);
  StageContext ctx{technique, now, settings, trianglesNow};
  runPipeline(backend, ctx, scratch);
  for (const auto& [id, buffer] : scratch)
    EXPECT_TRUE(sameWords(runner.buffers(), id, scratch, id)) << bufferSpec(id).qualifiedName();

  // The stage again, from a poisoned frame before.
  const BufferId radiance = BufferId::vct_light_voxels_radiance;
  PreviousFrame previous{&before, &trianglesBefore, {}};
  Buffer poison(radiance, glm::ivec3(16));
  for (uint32_t& w : poison.words) w = std::bit_cast<uint32_t>(-1.0f);
  previous.stash.put(std::move(poison));
  ctx.previous = &previous;
  BufferSet buffers;
  for (const auto& [id, buffer] : scratch)
    if (id != radiance) buffers.put(Buffer(buffer));
  backend.run(StageId::vct_light_voxels, ctx, buffers);
  const std::optional<VoxelBox> box = changedVoxelBox(ctx);
  ASSERT_TRUE(box.has_value());
  size_t kept = 0, shadowMoved = 0;
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const glm::ivec3 v(x, y, z);
        const glm::vec4 got = voxelValue(buffers.at(radiance), v);
        const glm::vec4 then = voxelValue(scratchBefore.at(radiance), v);
        const glm::vec4 want = voxelValue(scratch.at(radiance), v);
        if (got == glm::vec4(-1.0f)) {
          kept += y == 4 ? 1 : 0;
          EXPECT_EQ(then, want) << "voxel " << x << " " << y << " " << z << " kept but changed";
        } else {
          EXPECT_EQ(got, want) << "voxel " << x << " " << y << " " << z;
        }
        const glm::vec3 centre = glm::vec3(v) + 0.5f;
        const bool inBox = glm::all(glm::greaterThanEqual(centre, box->low)) &&
                           glm::all(glm::lessThanEqual(centre, box->high));
        if (y == 4 && then != want) {
          EXPECT_FALSE(inBox) << "the floor is outside the changed box";
          ++shadowMoved;
        }
      }
  EXPECT_GT(kept, 16u) << "the partial update relit every floor voxel";
  EXPECT_GT(shadowMoved, 4u) << "the blocker's shadow did not move on the floor";
}

}  // namespace voxgi::test
