// The stage runner (common/pipeline.h): which stages run, what a stage must leave behind, buffers
// kept apart by stage, and --stage names.
#include <set>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/pipeline.h"
#include "common/scene_io/scene_load.h"
#include "cpu/backend.h"
#include "tests/technique_cases.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// A backend whose stages write nothing, or a wrong buffer.
class BrokenBackend : public StageBackend {
 public:
  enum class Fault { nothing, foreign_buffer, unplanned_buffer };
  explicit BrokenBackend(Fault f) : fault_(f) {}
  std::string name() const override { return "broken"; }
  void run(StageId stage, const StageContext& ctx, BufferSet& buffers) override {
    cpu_.run(stage, ctx, buffers);
    const glm::ivec3 n(ctx.scene.grid.resolution);
    if (fault_ == Fault::nothing)
      for (const BufferSpec* b : stageBuffers(stageSpec(stage))) buffers.take(b->id);
    if (fault_ == Fault::foreign_buffer) buffers.put(Buffer(BufferId::vct_bounce_radiance, n));
    if (fault_ == Fault::unplanned_buffer)
      buffers.put(Buffer(BufferId::common_voxelize_emission, n));
  }

 private:
  Fault fault_;
  cpu::CpuBackend cpu_;
};

Scene smallScene() {
  return litQuad();
}

TEST(Pipeline, AStageMustWriteExactlyItsPlannedBuffers) {
  const Scene scene = smallScene();
  const Settings settings;
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  const StageContext ctx{vct(), scene, settings, tris};
  const StageSpec& voxelize = stageSpec(StageId::common_voxelize);
  {
    BrokenBackend nothing(BrokenBackend::Fault::nothing);
    BufferSet buffers;
    const StageOutputs out = runStage(nothing, voxelize, ctx, buffers);
    // the volumes but emission: the plan leaves out the emission and, as no later stage reads them,
    // the sums
    EXPECT_EQ(out.missing.size(), 3u);
    EXPECT_TRUE(out.unplanned.empty());
    EXPECT_THROW(runPipeline(nothing, ctx, buffers, &voxelize), std::logic_error);
  }
  for (const auto fault :
       {BrokenBackend::Fault::foreign_buffer, BrokenBackend::Fault::unplanned_buffer}) {
    BrokenBackend broken(fault);
    BufferSet buffers;
    const StageOutputs out = runStage(broken, voxelize, ctx, buffers);
    EXPECT_TRUE(out.missing.empty());
    ASSERT_EQ(out.unplanned.size(), 1u);
    EXPECT_NE(out.describe(voxelize, "broken").find("wrote unplanned"), std::string::npos);
  }
  cpu::CpuBackend cpu;
  BufferSet buffers;
  EXPECT_TRUE(runStage(cpu, voxelize, ctx, buffers).ok());
}

// bounce writes its own radiance and pyramid: light_voxels' and mip's stay as they were, and a
// stage that reads "the radiance" names which one.
TEST(Pipeline, BuffersAreKeptApartByStage) {
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  scene.grid.resolution = 16;
  scene.camera.width = scene.camera.height = 16;
  Settings settings;
  settings.vct.bounceCount = 1;
  const BufferSet all = runCpuUntil(scene, settings, "compose");
  const BufferSet direct = runCpuUntil(scene, settings, "mip");
  EXPECT_TRUE(sameWords(all, direct, BufferId::vct_light_voxels_radiance));
  EXPECT_TRUE(sameWords(all, direct, BufferId::vct_mip_radiance_mips6));
  EXPECT_FALSE(
      sameWords(all, BufferId::vct_bounce_radiance, all, BufferId::vct_light_voxels_radiance));
  for (const auto& [id, b] : all) EXPECT_TRUE(b.spec->id == id) << b.spec->qualifiedName();
  EXPECT_THROW(direct.at(BufferId::vct_bounce_radiance), std::logic_error);
}

TEST(Pipeline, RunsWhatThePlanSaysInGraphOrder) {
  const Scene scene = smallScene();
  Settings settings;
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  std::vector<std::string> names;
  for (const StageSpec* s : plannedStages(StageContext{vct(), scene, settings, tris}))
    names.push_back(s->qualifiedName());
  EXPECT_EQ(names, (std::vector<std::string>{"voxelize", "vct/light_voxels", "vct/mip", "gbuffer",
                                             "vct/trace_cones", "vct/compose"}));
  settings.vct.bounceCount = 1;
  const StageContext bounced{vct(), scene, settings, tris};
  const auto withBounce = plannedStages(bounced, &stageSpec(StageId::vct_bounce));
  ASSERT_EQ(withBounce.size(), 4u);
  EXPECT_EQ(withBounce.back()->id, StageId::vct_bounce);
}

// A backend that counts the stages it is asked to run.
class CountingBackend : public StageBackend {
 public:
  std::string name() const override { return "counting"; }
  void run(StageId stage, const StageContext& ctx, BufferSet& buffers) override {
    ++runs;
    cpu_.run(stage, ctx, buffers);
  }
  int runs = 0;

 private:
  cpu::CpuBackend cpu_;
};

// Nothing in the quad's scene emits light: every technique's plan keeps its last stage alone, no
// backend runs anything, and the image is black (EffectPlan::dark); plan.mode=full still runs
// every stage. A light brings the stages back.
TEST(Pipeline, ADarkSceneRunsNoStageAndItsImageIsBlack) {
  Scene scene = makeScene(quad(2, 0.3, {0.1, 0.1}, {0.9, 0.9}), unitGrid(16));
  scene.camera.width = scene.camera.height = 16;
  ASSERT_TRUE(scene.unlit());
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  for (const Technique& technique : techniques()) {
    Settings settings;
    const StageContext ctx{technique, scene, settings, tris};
    EXPECT_TRUE(ctx.plan.dark) << technique.name;
    const std::vector<const StageSpec*> planned = plannedStages(ctx);
    ASSERT_EQ(planned.size(), 1u) << technique.name;
    EXPECT_EQ(planned[0], technique.steps().back()) << technique.name;
    CountingBackend backend;
    BufferSet buffers;
    runPipeline(backend, ctx, buffers);
    EXPECT_EQ(backend.runs, 0) << technique.name;
    const Buffer& image = buffers.at(technique.image);
    EXPECT_EQ(image.extent, glm::ivec3(16, 16, 1));
    for (uint32_t w : image.words) ASSERT_EQ(w, 0u) << technique.name;
    settings.planMode = PlanMode::full;
    const StageContext full{technique, scene, settings, tris};
    EXPECT_FALSE(full.plan.dark);
    EXPECT_GT(plannedStages(full).size(), 3u) << technique.name;
  }
  scene.lights.push_back(testLight());
  Settings settings;
  EXPECT_FALSE((StageContext{vct(), scene, settings, tris}.plan.dark));
}

TEST(Pipeline, StageNamesResolveWithinTheTechnique) {
  EXPECT_EQ(resolveStage(vct(), "trace_cones").id, StageId::vct_trace_cones);
  EXPECT_EQ(resolveStage(vct(), "vct/trace_cones").id, StageId::vct_trace_cones);
  EXPECT_EQ(resolveStage(vct(), "gbuffer").id, StageId::common_gbuffer);
  EXPECT_EQ(resolveStage(vct(), "vct/gbuffer").id, StageId::common_gbuffer);
  EXPECT_THROW(resolveStage(vct(), "lpv/trace_cones"), InputError);
  EXPECT_THROW(resolveStage(vct(), "nonexistent"), InputError);
  EXPECT_THROW(findTechnique("nonexistent"), InputError);
}

// The cases a technique declares for the generic tests (tests/cases/<technique>.json) run every one
// of its stages between them, so the GPU diff and the determinism test reach each stage.
TEST(Pipeline, EveryStageRunsInSomeDeclaredCase) {
  for (const Technique& technique : techniques()) {
    for (const char* kind : {"determinism", "gpu"}) {
      std::set<const StageSpec*> planned;
      for (const TechniqueCase& c : techniqueCases(technique, kind)) {
        ASSERT_TRUE(c.error.empty()) << c.error;
        const Scene scene = caseScene(c);
        const EffectPlan plan = technique.plan(scene, caseSettings(c, scene));
        for (const StageSpec* s : technique.steps())
          if (plan.runs(s->id)) planned.insert(s);
      }
      for (const StageSpec* s : technique.steps())
        EXPECT_TRUE(planned.contains(s))
            << technique.name << "'s " << kind << " cases never run " << s->qualifiedName();
    }
  }
}

}  // namespace
}  // namespace voxgi::test
