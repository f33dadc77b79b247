// The effect planner: what it decides for a scene, and that skipping an effect the scene does not
// use leaves the image exactly as the full pipeline (plan.mode=full) renders it.
#include <gtest/gtest.h>

#include "common/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

bool planned(const EffectPlan& plan, const std::string& name) {
  for (const PlanItem& item : plan.items)
    if (item.name.find(name) != std::string::npos) return item.in;
  ADD_FAILURE() << "no plan item " << name;
  return false;
}

// A diffuse floor in view of a camera looking down -z, and a glossy quad behind the camera.
Scene floorAndHiddenMirror() {
  Scene scene = makeScene(quad(1, 0.25, {0.1, 0.1}, {0.9, 0.9}), unitGrid(32));
  Material mirror;
  mirror.specular = glm::vec3(0.9f);
  mirror.shininess = 200.0f;
  scene.materials.push_back(mirror);
  Scene wall = makeScene(quad(2, 0.99, {0.4, 0.4}, {0.6, 0.6}), unitGrid(32));  // behind the camera
  wall.meshes[0].material = 1;
  scene.meshes.push_back(wall.meshes[0]);
  scene.camera.position = {0.5, 0.5, 0.9};
  scene.camera.lookAt = {0.5, 0.25, 0.3};
  scene.camera.width = scene.camera.height = 64;
  Light light;
  light.position = {0.5, 0.8, 0.5};
  light.castsShadows = false;
  scene.lights.push_back(light);
  return scene;
}

TEST(EffectPlan, FollowsTheScene) {
  Scene scene = floorAndHiddenMirror();
  Settings settings;
  EffectPlan plan = planEffects(scene, settings);
  EXPECT_FALSE(plan.emission);
  EXPECT_FALSE(planned(plan, "emission volume"));
  EXPECT_FALSE(plan.specular) << "the glossy quad is behind the camera";
  EXPECT_TRUE(meshInView(scene, scene.meshes[0]));
  EXPECT_FALSE(meshInView(scene, scene.meshes[1]));
  EXPECT_EQ(plan.shadowLights, 0);
  EXPECT_FALSE(planned(plan, "shadow cones"));
  EXPECT_FALSE(plan.ambientOcclusion);
  EXPECT_FALSE(plan.runs("bounce"));
  EXPECT_TRUE(plan.runs("trace_cones"));

  scene.camera.lookAt = {0.5, 0.5, 2.0};  // turn around: the mirror is in view
  scene.lights[0].castsShadows = true;
  settings.ambientOcclusion = AmbientOcclusion::on;
  settings.bounceCount = 2;
  plan = planEffects(scene, settings);
  EXPECT_TRUE(plan.specular);
  EXPECT_EQ(plan.shadowLights, 1);
  EXPECT_TRUE(plan.ambientOcclusion);
  EXPECT_TRUE(planned(plan, "bounce"));
  EXPECT_EQ(plan.bounces, 2);

  settings.planMode = PlanMode::full;
  plan = planEffects(floorAndHiddenMirror(), settings);
  EXPECT_TRUE(plan.emission && plan.specular && plan.ambientOcclusion);
}

// Renders with the plan and with plan.mode=full; the full pipeline must really compute the skipped
// effects (their buffers exist) and the images must agree bit for bit.
void expectPlannedEqualsFull(const Scene& scene, Settings settings) {
  const BufferSet planned = runCpuUntil(scene, settings, "compose");
  settings.planMode = PlanMode::full;
  const BufferSet full = runCpuUntil(scene, settings, "compose");
  for (const char* extra :
       {"indirect_specular", "direct_specular", "ambient_occlusion", "pixel_emission", "emission"})
    EXPECT_TRUE(full.count(extra) == 1) << extra;
  EXPECT_EQ(planned.at("color").words, full.at("color").words);
}

TEST(EffectPlan, SkippedEffectsLeaveTheImageUnchanged) {
  {
    SCOPED_TRACE("floor, hidden mirror, no emission, shadowless light");
    const Scene scene = floorAndHiddenMirror();
    const EffectPlan plan = planEffects(scene, Settings{});
    ASSERT_FALSE(plan.specular || plan.emission || plan.ambientOcclusion);
    expectPlannedEqualsFull(scene, Settings{});
  }
  {
    SCOPED_TRACE("Cornell box: no glossy material, no AO");
    Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
    scene.grid.resolution = 32;
    scene.camera.width = scene.camera.height = 64;
    expectPlannedEqualsFull(scene, resolveSettings(scene.settings, scene.file, "default", {}));
  }
}

}  // namespace
}  // namespace voxgi::test
