// light_voxels against closed forms: a point light over a floor (irradiance I cos / r^2), hard and
// soft voxel shadows behind a blocker, the spot cut-off, emission, an emissive square as an area
// light, and Villegas' attenuation.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/lights.h"
#include "shaders/shared/lighting.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

constexpr int kN = 16;
constexpr double kH = 1.0 / kN;
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
  return glm::dvec3(0.5, 0.25, 1.0) / std::numbers::pi * 2.0 * cosine / (r * r);
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
  Settings settings;
  settings.vct.emitters = EmitterLighting::voxels;
  const BufferSet b = runCpuUntil(scene, settings, "light_voxels");
  const glm::vec4 r = voxelValue(b.at(BufferId::vct_light_voxels_radiance), {8, 8, 8});
  // Emission goes through voxelize's fixed-point sums: 2^-16 of the scene's largest emission.
  EXPECT_NEAR(r.r, 3.0f, 3.0f / 65536.0f);
  EXPECT_NEAR(r.g, 2.0f, 3.0f / 65536.0f);
  EXPECT_NEAR(r.b, 1.0f, 3.0f / 65536.0f);
  EXPECT_EQ(r.a, 1.0f);
}

// emitters.mode=area_lights: a floor voxel under an emitting square facing down takes albedo x L x
// F (Lambert's formula, exact), and the square's own voxels carry no emission: a voxel coplanar
// with the emitter gets no light from it.
TEST(LightVoxels, AreaLightLightsTheFloorByItsFormFactorAndItsVoxelsAreDark) {
  Material emitter;
  emitter.albedo = glm::vec3(0.5f);
  emitter.emission = glm::vec3(3.0f, 2.0f, 1.0f);
  // Centred over the middle of floor voxel (8, 4, 8).
  const double centre = 8.5 * kH;
  std::vector<Triangle> square =
      quad(1, 0.78, {centre - 0.25, centre - 0.25}, {centre + 0.25, centre + 0.25});
  for (Triangle& t : square) std::swap(t[1], t[2]);  // facing down
  Scene scene = makeScene(square, unitGrid(kN), emitter);
  Scene floor = floorScene(false);
  floor.lights.clear();
  scene.materials.push_back(floor.materials[0]);
  floor.meshes[0].material = 1;
  scene.meshes.push_back(floor.meshes[0]);
  Settings settings;
  settings.vct.emitters = EmitterLighting::area_lights;
  const BufferSet b = runCpuUntil(scene, settings, "light_voxels");
  const Buffer& radiance = b.at(BufferId::vct_light_voxels_radiance);
  // The floor voxel's centre lies 0.78 - 4.5/16 below the square's centre.
  const double f = squareFormFactor(0.25, 0.78 - 4.5 * kH);
  const glm::vec4 r = voxelValue(radiance, {8, 4, 8});
  ASSERT_GT(r.a, 0.0f);
  const glm::vec3 albedo = floor.materials[0].albedo;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(r[c] / r.a, albedo[c] * emitter.emission[c] * f, 1e-5) << c;
  // The emitter's voxel (layer 12): opaque, and dark.
  const glm::vec4 e = voxelValue(radiance, {8, 12, 8});
  EXPECT_GT(e.a, 0.0f);
  EXPECT_EQ(glm::vec3(e), glm::vec3(0.0f));
}

// More emissive triangles than area lights take: asked for explicitly, one line naming the scene
// and the setting; under the default (auto), their emission goes into the voxels.
TEST(LightVoxels, AreaLightsRefuseMoreTrianglesThanTheyTakeAndAutoKeepsThemInTheVoxels) {
  Material emitter;
  emitter.emission = glm::vec3(1.0f);
  std::vector<Triangle> strips;
  for (int k = 0; k < 33; ++k)
    for (const Triangle& t : quad(1, 0.5, {k / 40.0, 0.0}, {(k + 0.5) / 40.0, 1.0}))
      strips.push_back(t);
  const Scene scene = makeScene(strips, unitGrid(kN), emitter);
  Settings settings;
  settings.vct.emitters = EmitterLighting::area_lights;
  try {
    runCpuUntil(scene, settings, "light_voxels");
    FAIL() << "66 emissive triangles were taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("emitters.mode: area_lights takes at most 64"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(emittersFor(scene, EmitterLighting::automatic), EmitterLighting::voxels);
  const BufferSet b = runCpuUntil(scene, Settings{}, "light_voxels");
  // A voxel of the strips' plane (layer 8) holds their emission.
  EXPECT_GT(voxelValue(b.at(BufferId::vct_light_voxels_radiance), {0, 8, 8}).r, 0.0f);
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
