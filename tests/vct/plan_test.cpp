// Voxel cone tracing's effect planner (common/vct/plan.cpp): what it decides for a scene, and that
// skipping an effect the scene does not use leaves the image exactly as the full pipeline
// (plan.mode=full) renders it.
#include <gtest/gtest.h>

#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

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
  EffectPlan plan = vct().plan(scene, settings);
  EXPECT_FALSE(plan.on(Effect::emission));
  EXPECT_FALSE(planItemIn(plan, "emission volume"));
  EXPECT_FALSE(plan.on(Effect::specular)) << "the glossy quad is behind the camera";
  EXPECT_TRUE(meshInView(scene, scene.meshes[0]));
  EXPECT_FALSE(meshInView(scene, scene.meshes[1]));
  EXPECT_FALSE(planItemIn(plan, "shadow cones"));
  EXPECT_FALSE(plan.on(Effect::ambient_occlusion));
  EXPECT_FALSE(plan.runs(StageId::vct_bounce));
  EXPECT_TRUE(plan.runs(StageId::vct_trace_cones));
  // Every step of the technique is decided, so the runner never meets an unplanned stage.
  for (const StageSpec* s : vct().steps()) EXPECT_TRUE(plan.decides(s->id)) << s->qualifiedName();

  scene.camera.lookAt = {0.5, 0.5, 2.0};  // turn around: the mirror is in view
  scene.lights[0].castsShadows = true;
  settings.vct.ambientOcclusion = AmbientOcclusion::on;
  settings.vct.bounceCount = 2;
  plan = vct().plan(scene, settings);
  EXPECT_TRUE(plan.on(Effect::specular));
  EXPECT_TRUE(planItemIn(plan, "shadow cones"));
  EXPECT_TRUE(plan.on(Effect::ambient_occlusion));
  EXPECT_TRUE(planItemIn(plan, "bounce"));
  EXPECT_TRUE(plan.runs(StageId::vct_bounce));

  settings.planMode = PlanMode::full;
  plan = vct().plan(floorAndHiddenMirror(), settings);
  EXPECT_TRUE(plan.on(Effect::emission) && plan.on(Effect::specular) &&
              plan.on(Effect::ambient_occlusion));
}

// voxelize's dense sums are kept only where they are compared (voxgi diff and dump), under
// plan.mode=full, where a later stage reads them (lpv's geometry injection) and in a sequence (the
// next frame's update in part starts from them); the emission's with the emission volume.
TEST(EffectPlan, KeepsTheVoxelSumsOnlyWhereTheyAreComparedReadOrUpdated) {
  const Scene scene = floorAndHiddenMirror();
  const Technique& lpv = findTechnique("lpv");
  const auto sums = [&](const Technique& t, auto change) {
    Settings s;
    change(s);
    const EffectPlan p = t.plan(scene, s);
    EXPECT_EQ(planItemIn(p, "voxel sums"), p.on(Effect::voxel_sums));
    EXPECT_EQ(p.on(Effect::emission_sum), p.on(Effect::voxel_sums) && p.on(Effect::emission));
    return p.on(Effect::voxel_sums);
  };
  EXPECT_FALSE(sums(vct(), [](Settings&) {}));
  EXPECT_TRUE(sums(vct(), [](Settings& s) { s.inspect = true; }));
  EXPECT_TRUE(sums(vct(), [](Settings& s) { s.planMode = PlanMode::full; }));
  EXPECT_TRUE(sums(vct(), [](Settings& s) { s.sequence = true; }));
  EXPECT_TRUE(sums(lpv, [](Settings&) {}));  // propagate.occlusion=on by default
  EXPECT_FALSE(sums(lpv, [](Settings& s) { s.lpv.occlusion = LpvOcclusion::off; }));
}

// Renders with the plan and with plan.mode=full; the full pipeline must really compute the skipped
// effects (their buffers exist) and the images must agree bit for bit.
void expectPlannedEqualsFull(const Scene& scene, Settings settings) {
  const BufferSet planned = runCpuUntil(scene, settings, "compose");
  settings.planMode = PlanMode::full;
  const BufferSet full = runCpuUntil(scene, settings, "compose");
  using enum BufferId;
  for (BufferId extra :
       {vct_trace_cones_indirect_specular, vct_trace_cones_direct_specular,
        vct_trace_cones_ambient_occlusion, common_gbuffer_pixel_emission, common_voxelize_emission})
    EXPECT_TRUE(full.contains(extra)) << bufferSpec(extra).qualifiedName();
  EXPECT_TRUE(sameWords(planned, full, BufferId::vct_compose_color));
}

TEST(EffectPlan, SkippedEffectsLeaveTheImageUnchanged) {
  {
    SCOPED_TRACE("floor, hidden mirror, no emission, shadowless light");
    const Scene scene = floorAndHiddenMirror();
    const EffectPlan plan = vct().plan(scene, Settings{});
    ASSERT_FALSE(plan.on(Effect::specular) || plan.on(Effect::emission) ||
                 plan.on(Effect::ambient_occlusion));
    expectPlannedEqualsFull(scene, Settings{});
  }
  {
    SCOPED_TRACE("Cornell box: no glossy material, no AO");
    Scene scene = loadScene(sourcePath("scenes/cornell_box.json"));
    scene.grid.resolution = 32;
    scene.camera.width = scene.camera.height = 64;
    expectPlannedEqualsFull(scene,
                            resolveSettings(vct(), scene.settings, scene.file, "default", {}));
  }
}

}  // namespace
}  // namespace voxgi::test
