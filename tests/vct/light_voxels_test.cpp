// light_voxels against closed forms: a point light over a floor (irradiance I cos / r^2), hard and
// soft voxel shadows behind a blocker, the spot cut-off, emission, and Villegas' attenuation.
#include <cmath>

#include <gtest/gtest.h>

#include "shaders/shared/lighting.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

constexpr int kN = 16;
constexpr double kH = 1.0 / kN;
constexpr double kPi = 3.14159265358979323846;
const glm::dvec3 kLight(0.5, 0.9, 0.5);

// A floor at y = 0.27 (voxel layer 4) under a point light, optionally with a blocker at y = 0.6.
Scene floorScene(bool blocker) {
  auto tris = quad(1, 0.27, {0.0, 0.0}, {1.0, 1.0});
  if (blocker)
    for (const auto& t : quad(1, 0.6, {0.3, 0.3}, {0.7, 0.7})) tris.push_back(t);
  Material m;
  m.albedo = glm::vec3(0.5f, 0.25f, 1.0f);
  Scene scene = makeScene(tris, unitGrid(kN), m);
  Light l;
  l.position = kLight;
  l.intensity = glm::vec3(2.0f);
  scene.lights.push_back(l);
  return scene;
}

// albedo/pi * I * max(n.l, 0) / r^2 at the centre of floor voxel (i, 4, k), n from the voxel.
glm::dvec3 expectedFloor(const BufferSet& b, int i, int k) {
  const glm::dvec3 p((i + 0.5) * kH, 4.5 * kH, (k + 0.5) * kH);
  const glm::dvec3 n =
      glm::dvec3(glm::vec3(voxelValue(b.at(BufferId::common_voxelize_normal), {i, 4, k})));
  const glm::dvec3 d = kLight - p;
  const double r = glm::length(d);
  const double cosine = std::max(glm::dot(glm::normalize(n), d / r), 0.0);
  return glm::dvec3(0.5, 0.25, 1.0) / kPi * 2.0 * cosine / (r * r);
}

void expectRadiance(const BufferSet& b, glm::ivec3 v, glm::dvec3 expected) {
  const glm::vec4 r = voxelValue(b.at(BufferId::vct_light_voxels_radiance), v);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r[c], expected[c], 1e-5 * expected[c] + 1e-9) << c;
  EXPECT_EQ(r.a, 1.0f);
}

TEST(LightVoxels, PointLightOverFloorIsIrradianceTimesAlbedoOverPi) {
  Settings s;
  s.vct.voxelShadow = VoxelShadow::none;
  Scene scene = floorScene(false);
  BufferSet b = runCpuUntil(scene, s, "light_voxels");
  // The quad's winding decides its normal; put the light on the lit side.
  if (voxelValue(b.at(BufferId::common_voxelize_normal), {8, 4, 8}).y < 0.0f) {
    for (auto& t : scene.meshes[0].triangles) std::swap(t.y, t.z);
    b = runCpuUntil(scene, s, "light_voxels");
  }
  for (glm::ivec2 ik : {glm::ivec2(8, 8), glm::ivec2(0, 0), glm::ivec2(15, 3), glm::ivec2(5, 12)})
    expectRadiance(b, {ik.x, 4, ik.y}, expectedFloor(b, ik.x, ik.y));
  // Empty voxels stay empty.
  EXPECT_EQ(voxelValue(b.at(BufferId::vct_light_voxels_radiance), {8, 8, 8}), glm::vec4(0.0f));
}

Scene litFloorWithBlocker() {
  Scene scene = floorScene(true);
  const BufferSet b = runCpuUntil(scene, Settings{}, "voxelize");
  if (voxelValue(b.at(BufferId::common_voxelize_normal), {0, 4, 0}).y < 0.0f)
    for (auto& t : scene.meshes[0].triangles) std::swap(t.y, t.z);
  return scene;
}

TEST(LightVoxels, HardVoxelShadowBehindABlocker) {
  const Scene scene = litFloorWithBlocker();
  Settings s;
  s.vct.voxelShadow = VoxelShadow::hard;
  const BufferSet b = runCpuUntil(scene, s, "light_voxels");
  EXPECT_EQ(voxelValue(b.at(BufferId::vct_light_voxels_radiance), {8, 4, 8}),
            glm::vec4(0, 0, 0, 1));                      // under the blocker
  expectRadiance(b, {0, 4, 0}, expectedFloor(b, 0, 0));  // in the open
  expectRadiance(b, {15, 4, 15}, expectedFloor(b, 15, 15));
}

TEST(LightVoxels, SoftVoxelShadowIsPartialAndMonotoneInKappa) {
  const Scene scene = litFloorWithBlocker();
  Settings s;
  s.vct.voxelShadow = VoxelShadow::none;
  const float open =
      voxelValue(runCpuUntil(scene, s, "light_voxels").at(BufferId::vct_light_voxels_radiance),
                 {8, 4, 8})
          .r;
  s.vct.voxelShadow = VoxelShadow::soft;
  float previous = open;
  for (float kappa : {0.5f, 2.0f, 8.0f, 64.0f}) {
    s.vct.voxelShadowKappa = kappa;
    const float r =
        voxelValue(runCpuUntil(scene, s, "light_voxels").at(BufferId::vct_light_voxels_radiance),
                   {8, 4, 8})
            .r;
    if (previous > 0.0f) {
      EXPECT_LT(r, previous) << "kappa " << kappa;
    }
    EXPECT_GE(r, 0.0f);
    previous = r;
  }
  EXPECT_EQ(previous, 0.0f);  // kappa large enough: fully occluded
}

TEST(LightVoxels, SpotLightCutsOffOutsideItsCone) {
  Scene scene = litFloorWithBlocker();
  scene.meshes[0].triangles.resize(2);  // floor only
  scene.lights[0].type = Light::Type::spot;
  scene.lights[0].direction = {0.0, -1.0, 0.0};
  scene.lights[0].spotAngleDeg = 40.0f;  // reaches the floor within 0.63 * tan(20 deg) = 0.23
  Settings s;
  const BufferSet b = runCpuUntil(scene, s, "light_voxels");
  expectRadiance(b, {8, 4, 8}, expectedFloor(b, 8, 8));
  EXPECT_EQ(voxelValue(b.at(BufferId::vct_light_voxels_radiance), {2, 4, 8}),
            glm::vec4(0, 0, 0, 1));
}

TEST(LightVoxels, EmissionIsAddedWithoutLights) {
  Material m;
  m.emission = glm::vec3(3.0f, 2.0f, 1.0f);
  const Scene scene = makeScene(quad(2, 0.51, {0.1, 0.1}, {0.9, 0.9}), unitGrid(kN), m);
  const BufferSet b = runCpuUntil(scene, Settings{}, "light_voxels");
  const glm::vec4 r = voxelValue(b.at(BufferId::vct_light_voxels_radiance), {8, 8, 8});
  // Emission goes through voxelize's fixed-point sums: 2^-16 of the scene's largest emission.
  EXPECT_NEAR(r.r, 3.0f, 3.0f / 65536.0f);
  EXPECT_NEAR(r.g, 2.0f, 3.0f / 65536.0f);
  EXPECT_NEAR(r.b, 1.0f, 3.0f / 65536.0f);
  EXPECT_EQ(r.a, 1.0f);
}

TEST(LightVoxels, NormalWeightedAttenuation) {
  using shared::normalWeightedAttenuation;
  // An axis normal reduces to the cosine.
  EXPECT_FLOAT_EQ(normalWeightedAttenuation({0, 1, 0}, {0.6f, 0.8f, 0}), 0.8f);
  EXPECT_FLOAT_EQ(normalWeightedAttenuation({0, 1, 0}, {0.6f, -0.8f, 0}), 0.0f);
  // A diagonal normal: W = (1/2, 1/2, 0), D = (1, 0, 0) -> 1/2 (the cosine would be 0.707).
  const float s = std::sqrt(0.5f);
  EXPECT_NEAR(normalWeightedAttenuation({s, s, 0}, {1, 0, 0}), 0.5f, 1e-6f);
  // The light behind the dominant faces gives nothing.
  EXPECT_FLOAT_EQ(normalWeightedAttenuation({s, s, 0}, {-1, 0, 0}), 0.0f);
}

}  // namespace
}  // namespace voxgi::test
