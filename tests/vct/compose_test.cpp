// The compose stage (docs/stages/vct/compose.md): each pixel's colour is its materials times the
// light terms trace_cones wrote, plus its emission, with AO on the indirect diffuse term only
// when asked, and the background where it sees no surface. The sum is restated here in double
// from the buffers, so a term read from the wrong buffer or dropped shows.
#include <gtest/gtest.h>

#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// The bunny (glossy, a point light) with an emitting box, at 16^3 and 48 pixels.
Scene glossyEmittingBunny() {
  Scene scene = loadScene(sourcePath("scenes/bunny.json"));
  scene.grid.resolution = 16;
  scene.camera.width = scene.camera.height = 48;
  for (Material& m : scene.materials)
    if (m.specular == glm::vec3(0.0f)) m.emission = glm::vec3(0.5f, 0.25f, 0.125f);
  return scene;
}

void expectComposedFromTheTerms(const Scene& scene, const Settings& settings, bool ao) {
  const BufferSet b = runCpuUntil(scene, settings, "compose");
  using enum BufferId;
  const Buffer &color = b.at(vct_compose_color), &object = b.at(common_gbuffer_object_id);
  const auto term = [&](BufferId id, size_t e) {
    return glm::dvec3(b.at(id).vec3At(e));  // at() throws if the plan dropped a term
  };
  size_t surfaces = 0, background = 0, occluded = 0;
  for (size_t e = 0; e < color.elementCount(); ++e) {
    glm::dvec3 expected(scene.background);
    if (object.get<uint32_t>(e, 0) != 0) {
      const double occlusion = ao ? b.at(vct_trace_cones_ambient_occlusion).get<float>(e, 0) : 0.0;
      occluded += occlusion > 0.0;
      expected =
          term(common_gbuffer_pixel_albedo, e) *
              (term(vct_trace_cones_direct_diffuse, e) +
               term(vct_trace_cones_indirect_diffuse, e) * (1.0 - occlusion)) +
          term(common_gbuffer_pixel_specular, e) * (term(vct_trace_cones_direct_specular, e) +
                                                    term(vct_trace_cones_indirect_specular, e)) +
          term(common_gbuffer_pixel_emission, e);
      ++surfaces;
    } else {
      ++background;
    }
    const glm::dvec3 got(color.vec3At(e));
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(got[c], expected[c], 1e-6 * std::abs(expected[c]) + 1e-9)
          << "pixel " << e << " channel " << c;
  }
  EXPECT_GT(surfaces, 500u);
  EXPECT_GT(background, 0u);
  if (ao) {
    EXPECT_GT(occluded, 100u);
  }
}

TEST(Compose, ColourIsTheMaterialsTimesTheLightTermsPlusEmission) {
  expectComposedFromTheTerms(glossyEmittingBunny(), Settings{}, false);
}

// ao.mode=on darkens the indirect diffuse term by the cones' occlusion, and nothing else.
TEST(Compose, AmbientOcclusionScalesTheIndirectDiffuseTermOnly) {
  Settings settings;
  settings.vct.ambientOcclusion = AmbientOcclusion::on;
  expectComposedFromTheTerms(glossyEmittingBunny(), settings, true);
}

}  // namespace
}  // namespace voxgi::test
