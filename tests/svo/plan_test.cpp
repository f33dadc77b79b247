// The octree's effect planner (common/svo/plan.cpp; docs/effect-plan.md).
#include <gtest/gtest.h>

#include "common/scene/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// The octree's plan: emission and the specular cone from the materials of meshes and clouds, and
// the full pipeline gives the same image with the extra buffers.
TEST(SvoPlan, FollowsTheSceneAndTheFullPlanChangesNothing) {
  const Technique& svo = findTechnique("svo");
  Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
  scene.grid.resolution = 16;
  scene.camera.width = scene.camera.height = 32;
  Settings settings = techniqueDefaults(svo);
  const EffectPlan plan = svo.plan(scene, settings);
  EXPECT_TRUE(planItemIn(plan, "emission per pixel"));
  EXPECT_FALSE(planItemIn(plan, "specular cone"));
  const BufferSet lean = runCpuUntil(svo, scene, settings, "shade");
  EXPECT_FALSE(lean.contains(BufferId::svo_shade_indirect_specular));
  settings.planMode = PlanMode::full;
  const BufferSet full = runCpuUntil(svo, scene, settings, "shade");
  EXPECT_TRUE(full.contains(BufferId::svo_shade_indirect_specular));
  EXPECT_TRUE(sameWords(lean, full, BufferId::svo_shade_color));
  Scene glossy = cornellBoxCloud(2000, true);
  EXPECT_TRUE(planItemIn(svo.plan(glossy, techniqueDefaults(svo)), "specular cone"));
}

}  // namespace
}  // namespace voxgi::test
