// The planner in time (common/frame_plan.h): on each technique's "motion" case
// (tests/cases/<technique>.json), a sequence in which the camera moves, nothing moves, a light
// moves and a mesh moves; every frame reached incrementally (the stages frameSteps runs, the rest
// reused) equals the frame rendered from scratch bit for bit on the CPU, and the steps reuse what
// the change allows: no volume stage when only the camera moved, nothing when nothing did, and
// no voxelization when only a light did.
#include <algorithm>
#include <cstring>

#include <gtest/gtest.h>

#include "common/frame_plan.h"
#include "common/scene_io/scene_load.h"
#include "common/voxelize_update.h"
#include "cpu/backend.h"
#include "tests/frame_sequences.h"
#include "tests/technique_cases.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

class FramePlan : public testing::TestWithParam<TechniqueCase> {};

TEST_P(FramePlan, IncrementalFramesEqualFramesFromScratch) {
  cpu::CpuBackend cpu;
  expectIncrementalFramesEqualScratch(GetParam(), cpu);
}

INSTANTIATE_TEST_SUITE_P(Techniques, FramePlan, testing::ValuesIn(allTechniqueCases("motion")),
                         [](const testing::TestParamInfo<TechniqueCase>& p) {
                           return p.param.label;
                         });

// update.interval=3 on vct's and lpv's first motion cases: volumes of frames 0, 3 and 6.
TEST(FramePlan, VolumesUpdateEveryIntervalFrames) {
  cpu::CpuBackend cpu;
  for (const char* technique : {"vct", "lpv"})
    for (const TechniqueCase& c : requiredCases(technique, "motion")) {
      SCOPED_TRACE(c.label);
      expectVolumesUpdateEveryInterval(c, cpu, 3);
      break;
    }
}

// svo's motion case under propagate.carry=on: the carried light is the same whether the frames
// were reached incrementally or from scratch.
TEST(FramePlan, CarriedLightIsTheSameFromScratch) {
  cpu::CpuBackend cpu;
  for (const TechniqueCase& c : requiredCases("svo", "motion"))
    expectCarriedFramesEqualScratch(c, cpu);
}

TEST(FramePlan, LightVoxelsRelightsOnlyWhatTheMovedMeshCanReach) {
  cpu::CpuBackend cpu;
  expectPartialRelightEqualsScratch(cpu);
}

// A sequence's frames keep voxelize's sums (Settings::sequence, which FrameRunner sets), so that a
// frame in which a small mesh moved updates the frame before's sums in part: with the buffers the
// runner's frame left, the next frame's voxelize finds all its update needs. A still image drops
// the sums, and the same frame after it would be voxelized whole.
TEST(FramePlan, ASequenceKeepsWhatVoxelizesUpdateInPartStartsFrom) {
  const std::vector<TechniqueCase> cases = requiredCases("vct", "motion");
  ASSERT_FALSE(cases.empty());
  const auto c = cases.begin();
  const std::vector<Scene> frames = motionFrames(caseScene(*c));
  const Scene &before = frames[3], &now = frames[4];  // frame 4 moves the smallest mesh
  cpu::CpuBackend cpu;
  FrameRunner runner(vct(), cpu);
  for (size_t f = 0; f <= 3; ++f) runner.run(frames[f], caseSettings(*c, frames[f]));
  const VoxelTriangles trianglesBefore = prepareVoxelTriangles(before, before.grid);
  const VoxelTriangles trianglesNow = prepareVoxelTriangles(now, now.grid);
  BufferSet still;
  runPipeline(cpu, StageContext{vct(), before, caseSettings(*c, before), trianglesBefore}, still,
              &stageSpec(StageId::common_voxelize));
  for (const bool sequence : {true, false}) {
    SCOPED_TRACE(sequence ? "a sequence" : "after a still image");
    const Settings settings = sequence ? runner.settings() : caseSettings(*c, now);
    EXPECT_EQ(settings.sequence, sequence);
    PreviousFrame previous{&before, &trianglesBefore, {}};
    for (const BufferSpec* spec : stageBuffers(stageSpec(StageId::common_voxelize)))
      if (const Buffer* b = (sequence ? runner.buffers() : still).find(spec->id))
        previous.stash.put(Buffer(*b));
    StageContext ctx{vct(), now, settings, trianglesNow};
    ctx.previous = &previous;
    const std::optional<MovedTriangles> moved = movedTriangles(ctx, ctx.plan.on(Effect::emission));
    EXPECT_EQ(moved.has_value(), sequence);
    if (moved) {
      EXPECT_EQ(moved->now.size(), 1u);
    }
  }
}

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
  EXPECT_EQ(c.parts, stage_reads::kScene);
  size_t all = 0;
  for (const Mesh& m : a.meshes) all += m.triangles.size();
  const size_t bunny = a.meshes[0].triangles.size();
  EXPECT_EQ(c.describe(),
            "1 mesh moved: " + std::to_string(bunny) + " of " + std::to_string(all) +
                " triangles (" +
                std::to_string(int(std::lround(100.0 * double(bunny) / double(all)))) +
                " %); 1 light changed; the camera moved");
}

// A frame's triangle setup that keeps the unmoved meshes' triangles from the frame before gives
// the triangles, mesh ranges and counts of a setup from scratch, byte for byte.
TEST(FramePlan, TriangleSetupKeepsTheUnmovedMeshes) {
  const Scene before = loadScene(sourcePath("scenes/bunny.json"));
  Scene now = before;
  const size_t moved = smallestMesh(now);
  for (glm::dvec3& p : now.meshes[moved].positions) p += glm::dvec3(0.0, -0.3, 0.1);
  std::vector<bool> unchanged(now.meshes.size(), true);
  unchanged[moved] = false;
  const VoxelTriangles scratch = prepareVoxelTriangles(now, now.grid);
  const VoxelTriangles kept =
      prepareVoxelTriangles(now, now.grid, prepareVoxelTriangles(before, before.grid), unchanged);
  ASSERT_EQ(kept.triangles.size(), scratch.triangles.size());
  EXPECT_EQ(std::memcmp(kept.triangles.data(), scratch.triangles.data(),
                        scratch.triangles.size() * sizeof(shared::VoxelTriangle)),
            0);
  EXPECT_EQ(kept.meshFirst, scratch.meshFirst);
  EXPECT_EQ(kept.clipped, scratch.clipped);
  EXPECT_EQ(kept.emissionScale, scratch.emissionScale);
  EXPECT_NE(
      std::memcmp(&prepareVoxelTriangles(before, before.grid).triangles[kept.meshFirst[moved]],
                  &kept.triangles[kept.meshFirst[moved]], sizeof(shared::VoxelTriangle)),
      0);  // the moved mesh was set up again
}

}  // namespace
}  // namespace voxgi::test
