// Light propagation volumes' effect planner (docs/effect-plan.md): when the rsm stage runs.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/lpv/light_scenes.h"

namespace voxgi::test {
namespace {

TEST(LpvPlan, RsmRunsForAnalyticLightsAndAreaLights) {
  Scene scene = makeScene(cubeFaces(0.2, 0.8), unitGrid(16), grey(glm::vec3(0.5f)));
  const Technique& t = lpvTechnique();
  Settings settings = techniqueDefaults(t);
  EffectPlan plan = t.plan(scene, settings);
  EXPECT_TRUE(plan.dark);  // nothing emits light
  EXPECT_EQ(plan.whySkipped(StageId::lpv_rsm), kDarkReason);
  scene.background = glm::vec3(0.2f);  // a sky lights it, but no light makes a shadow map
  plan = t.plan(scene, settings);
  EXPECT_FALSE(plan.runs(StageId::lpv_rsm));
  EXPECT_EQ(plan.whySkipped(StageId::lpv_rsm), "no analytic lights");
  EXPECT_FALSE(plan.on(Effect::direct_light));
  scene.lights.push_back(pointLight({0.5, 0.5, 0.5}, glm::vec3(1.0f)));
  Light sun;
  sun.type = Light::Type::directional;
  scene.lights.push_back(sun);
  plan = t.plan(scene, settings);
  EXPECT_TRUE(plan.runs(StageId::lpv_rsm));
  EXPECT_TRUE(plan.on(Effect::direct_light));
  EXPECT_EQ(plan.maps, glm::ivec2(256, 7)) << "six faces and one box";
  // An emissive quad: two area lights of six faces each (emitters.mode=auto), or VPLs of its own.
  scene.lights.clear();
  addEmitter(scene, downwardSquare(0.7, 0.4, 0.6), glm::vec3(1.0f));
  plan = t.plan(scene, settings);
  EXPECT_TRUE(plan.runs(StageId::lpv_rsm));
  EXPECT_EQ(plan.maps, glm::ivec2(256, 12));
  settings.vct.emitters = EmitterLighting::voxels;
  plan = t.plan(scene, settings);
  EXPECT_FALSE(plan.runs(StageId::lpv_rsm));
  EXPECT_EQ(plan.whySkipped(StageId::lpv_rsm), "no analytic lights and emitters.mode=voxels");
}
}  // namespace
}  // namespace voxgi::test
